# The students' tree stays green: `raylab distribute` writes it; its figures build alone, and
# `raylab grade` then builds what it needs; its own test suite (the one its README tells students to
# run) passes with no lab written (each lab skipped), with lab 1 written (lab 1 passes, the others
# skipped) and with every lab written (all pass, none skipped); the instructors' commands it does not
# build (raylab numerics) say so.
#
#   cmake -DRAYLAB=<raylab program> -DSOLUTIONS=<solutions/> -DWORK=<scratch folder> [-DGENERATOR=...]
#         [-DCCACHE=<ccache>] -P tests/labs/students_tree.cmake
# Every program runs from an argument vector (execute_process), never through a shell.
cmake_minimum_required(VERSION 3.22) # if(IN_LIST)

foreach(var RAYLAB SOLUTIONS WORK)
  if(NOT ${var})
    message(FATAL_ERROR "students' tree: -D${var}=... is required")
  endif()
endforeach()
set(tree ${WORK}/tree)
# The build folder inside the tree, as build/ is in the repository: the compiler then sees the same
# relative paths as the repository's own build, so that ccache (with CCACHE_BASEDIR, .ci/run) reuses
# its objects of the framework and the grader instead of compiling them again.
set(build ${tree}/build)

set(STEP_PREFIX "students' tree")
include(${CMAKE_CURRENT_LIST_DIR}/script_steps.cmake)

# ctest of the students' tree: it must pass, with `passed` labs passed and the others skipped.
function(suite_passes passed)
  run(output 0 ${CMAKE_COMMAND} --build ${build} -j 2)
  run(output 0 ${CMAKE_CTEST_COMMAND} --test-dir ${build} -j 2)
  expect("${output}" "100% tests passed" "the suite passes")
  foreach(n 1 2 3 4 5)
    set(test "lab ${n}: its function checks and figures against the references (raylab grade --lab ${n})")
    set(verdict "***Skipped")
    if(n IN_LIST passed)
      set(verdict "Passed")
    endif()
    # ctest's result line: "k/N Test #i: <name> .....   <verdict>".
    string(REGEX MATCHALL "Test #[0-9]+: [^\n]*" results "${output}")
    set(found "")
    foreach(line IN LISTS results)
      string(FIND "${line}" "${test}" named)
      string(FIND "${line}" "${verdict}" said)
      if(NOT named EQUAL -1 AND NOT said EQUAL -1)
        set(found yes)
      endif()
    endforeach()
    if(found STREQUAL "")
      message(FATAL_ERROR "students' tree: lab ${n} should be ${passed} passed, the others skipped:\n${output}")
    endif()
  endforeach()
endfunction()

file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
run(output 0 ${RAYLAB} distribute ${tree})
set(configure ${CMAKE_COMMAND} -S ${tree} -B ${build} -DCMAKE_BUILD_TYPE=Release -DRAYLAB_LTO=OFF)
if(GENERATOR)
  list(APPEND configure -G ${GENERATOR})
endif()
if(CCACHE)
  list(APPEND configure -DCMAKE_CXX_COMPILER_LAUNCHER=${CCACHE})
endif()
run(output 0 ${configure})

# The README's first command builds the figures alone (raylab, no grading program): `raylab grade`
# then builds the grading programs first.
run(output 0 ${CMAKE_COMMAND} --build ${build} --target figures -j 2)
if(EXISTS ${build}/bin/raylab-agent)
  message(FATAL_ERROR "students' tree: building the figures built the grading programs too")
endif()
run(output 3 ${build}/bin/raylab --lang en grade --lab 1)
expect("${output}" "building the grading programs first" "raylab grade after the figures' build")
if(NOT EXISTS ${build}/bin/raylab-agent)
  message(FATAL_ERROR "students' tree: raylab grade did not build its grading programs")
endif()

suite_passes("")

# The instructors' commands whose code holds a lab's answer are not built here, and say so.
foreach(command "numerics" "study;intersection")
  run(output 1 ${build}/bin/raylab ${command})
  expect("${output}" "is an instructors' command" "raylab ${command}")
endforeach()

# A student's lab: the solution's files written over the stubs (anew, so they are newer than the build).
function(write_lab folder)
  file(GLOB files ${SOLUTIONS}/${folder}/*.cpp)
  foreach(file IN LISTS files)
    get_filename_component(name ${file} NAME)
    file(READ ${file} text)
    file(WRITE ${tree}/labs/${folder}/${name} "${text}")
  endforeach()
endfunction()

write_lab(lab1_first_image)
suite_passes("1")

foreach(folder lab2_primary_rays lab3_sphere lab4_lookat_camera lab5_antialiasing)
  write_lab(${folder})
endforeach()
suite_passes("1;2;3;4;5")
message(STATUS "students' tree: its suite passes with 0, 1 and 5 labs written")
