# The steps of the tests written as CMake scripts (toy_lab.cmake, students_tree.cmake,
# course_subset.cmake): each sets STEP_PREFIX ("toy lab") before including this file, and `tree` and
# `build` (the tree's folder and its build folder) before it copies or configures a tree. Programs
# run from an argument vector (execute_process), never through a shell.

# The steps check raylab's English: what they run speaks English whatever the locale of the one who
# runs the suite, as tests/support/doctest_main.cpp makes the test programs do (LC_ALL and LC_MESSAGES
# unset, LANG=C), the locale's character set kept in LC_CTYPE. A step of French asks --lang fr.
foreach(variable LC_ALL LC_CTYPE LANG)
  if(NOT "$ENV{${variable}}" STREQUAL "")
    set(ENV{LC_CTYPE} "$ENV{${variable}}")
    break()
  endif()
endforeach()
unset(ENV{LC_ALL})
unset(ENV{LC_MESSAGES})
set(ENV{LANG} C)

# run(NAME EXPECTED_STATUS COMMAND...): runs COMMAND in WORK, fails unless it exits with
# EXPECTED_STATUS ("nonzero" for any failure); its output is in the variable NAME.
function(run name expected)
  execute_process(COMMAND ${ARGN} WORKING_DIRECTORY ${WORK} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  string(REPLACE ";" " " shown "${ARGN}")
  message(STATUS "${STEP_PREFIX}: ${shown} -> ${status}")
  if((expected STREQUAL "nonzero" AND status EQUAL 0) OR (NOT expected STREQUAL "nonzero" AND NOT status EQUAL expected))
    message(FATAL_ERROR "${STEP_PREFIX}: `${shown}` exited with ${status}, expected ${expected}:\n${out}${err}")
  endif()
  set(${name} "${out}${err}" PARENT_SCOPE)
endfunction()

# expect(TEXT NEEDLE WHAT): fails unless TEXT contains NEEDLE.
function(expect text needle what)
  string(FIND "${text}" "${needle}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "${STEP_PREFIX}: ${what}: no \"${needle}\" in:\n${text}")
  endif()
endfunction()

# build(TARGET...): builds those targets of the tree's build folder (the variable `build`), 2 jobs.
function(build)
  run(output 0 ${CMAKE_COMMAND} --build ${build} --target ${ARGN} -j 2)
endfunction()

# copy_tree(SOURCE DESTINATION): the files of the source tree as git lists them (tracked, and new
# ones .gitignore does not exclude: no build folder, no out/) copied into DESTINATION, emptied first.
function(copy_tree source destination)
  find_program(git git)
  if(NOT git)
    message(FATAL_ERROR "${STEP_PREFIX}: copying the tree needs git (it lists the tree's files)")
  endif()
  execute_process(COMMAND ${git} -C ${source} ls-files --cached --others --exclude-standard
                  RESULT_VARIABLE status OUTPUT_VARIABLE listed ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${STEP_PREFIX}: `git ls-files` in ${source} failed (not a git work tree?): ${err}")
  endif()
  file(REMOVE_RECURSE ${destination})
  string(REPLACE "\n" ";" files "${listed}")
  set(count 0)
  foreach(file IN LISTS files)
    # A tracked file deleted from the work tree is not part of the tree.
    if(file AND EXISTS ${source}/${file})
      get_filename_component(folder ${destination}/${file} DIRECTORY)
      file(COPY ${source}/${file} DESTINATION ${folder})
      math(EXPR count "${count} + 1")
    endif()
  endforeach()
  message(STATUS "${STEP_PREFIX}: ${count} files of ${source} copied to ${destination}")
endfunction()

# configure_tree(OUTPUT_VARIABLE [cmake argument...]): configures the tree (the variable `tree`) in
# its build folder (`build`), Release without link-time optimisation (quicker links: these tests
# are not about speed), with GENERATOR and the compiler cache CCACHE when the script was given them.
function(configure_tree name)
  set(configure ${CMAKE_COMMAND} -S ${tree} -B ${build} -DCMAKE_BUILD_TYPE=Release -DRAYLAB_LTO=OFF ${ARGN})
  if(GENERATOR)
    list(APPEND configure -G ${GENERATOR})
  endif()
  if(CCACHE)
    list(APPEND configure -DCMAKE_CXX_COMPILER_LAUNCHER=${CCACHE})
  endif()
  run(output 0 ${configure})
  set(${name} "${output}" PARENT_SCOPE)
endfunction()

# run_step(): calls the script's function step_<STEP> (dashes as underscores); an unknown step is an error.
macro(run_step)
  string(REPLACE "-" "_" step ${STEP})
  if(NOT COMMAND step_${step})
    message(FATAL_ERROR "${STEP_PREFIX}: no step ${STEP}")
  endif()
  cmake_language(CALL step_${step})
endmacro()
