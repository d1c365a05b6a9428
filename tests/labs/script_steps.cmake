# The steps of the tests written as CMake scripts (toy_lab.cmake, students_tree.cmake): each sets
# STEP_PREFIX ("toy lab") before including this file. Programs run from an argument vector
# (execute_process), never through a shell.

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

# run_step(): calls the script's function step_<STEP> (dashes as underscores); an unknown step is an error.
macro(run_step)
  string(REPLACE "-" "_" step ${STEP})
  if(NOT COMMAND step_${step})
    message(FATAL_ERROR "${STEP_PREFIX}: no step ${STEP}")
  endif()
  cmake_language(CALL step_${step})
endmacro()
