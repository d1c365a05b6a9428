# The students' tree stays green: `raylab distribute` writes it; its figures build alone, and
# `raylab grade` then builds what it needs; its own test suite (the one its README tells students to
# run) passes with no lab written (each lab skipped), with lab 1 written (lab 1 passes, the others
# skipped) and with every lab written (all pass, none skipped); the instructors' commands it does not
# build (raylab numerics) say so; a student's own correct labs get every point there, as grade-class
# gives them.
#
#   cmake -DSTEP=<step> -DRAYLAB=<raylab program> -DSOLUTIONS=<solutions/> -DWORK=<scratch folder>
#         -DVARIANT=<applied variant> [-DGENERATOR=...] [-DCCACHE=<ccache>] -P tests/labs/students_tree.cmake
# It runs in steps, one ctest test each (tests/CMakeLists.txt), each in the tree the steps before it
# left (ctest prints nothing while a test runs; with a warm compiler cache each step lasts seconds): distribute,
# build-framework, build-figures, grade-builds, build-suite, suite-none, instructors-commands,
# suite-lab1, broken-lab, two-at-once, suite-all, variants. It builds the tree on its own, from its own files: nothing of the
# repository's build is linked (a compiler cache may only skip compiling the same command twice).
# Every program runs from an argument vector (execute_process), never through a shell.
cmake_minimum_required(VERSION 3.22) # if(IN_LIST)

foreach(var STEP RAYLAB SOLUTIONS WORK)
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

# ctest of the students' tree, after building all of it: it must pass, with `passed` labs passed and
# the others skipped.
# The tree's labs (those raylab distribute wrote, the course's): their folders' names and numbers.
function(tree_labs folders_var numbers_var)
  file(GLOB paths LIST_DIRECTORIES true ${tree}/labs/lab*_*)
  set(folders "")
  set(numbers "")
  foreach(path IN LISTS paths)
    get_filename_component(folder ${path} NAME)
    string(REGEX MATCH "^lab([0-9]+)_" matched "${folder}")
    if(IS_DIRECTORY ${path} AND matched)
      list(APPEND folders ${folder})
      list(APPEND numbers ${CMAKE_MATCH_1})
    endif()
  endforeach()
  if(NOT numbers)
    message(FATAL_ERROR "students' tree: no lab folder in ${tree}/labs")
  endif()
  set(${folders_var} ${folders} PARENT_SCOPE)
  set(${numbers_var} ${numbers} PARENT_SCOPE)
endfunction()

function(suite_passes passed)
  run(output 0 ${CMAKE_COMMAND} --build ${build} -j 2)
  run(output 0 ${CMAKE_CTEST_COMMAND} --test-dir ${build} -j 2)
  expect("${output}" "100% tests passed" "the suite passes")
  tree_labs(folders numbers)
  foreach(n IN LISTS numbers)
    set(test "lab ${n}: its function checks and figures against the references (raylab grade --lab ${n})")
    set(verdict "***Skipped")
    if(n IN_LIST passed)
      set(verdict "Passed")
    endif()
    # ctest's result line: "k/N Test #i: <name> .....   <verdict>".
    string(REGEX MATCHALL "Test +#[0-9]+: [^\n]*" results "${output}") # "Test  #1" once there are 10 tests
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

# 1. The students' tree, written by `raylab distribute`, configured.
function(step_distribute)
  file(REMOVE_RECURSE ${WORK})
  file(MAKE_DIRECTORY ${WORK})
  run(output 0 ${RAYLAB} distribute ${tree})
  configure_tree(output)
endfunction()

# 2. The framework and the grader, alone first (the longest part of a build from nothing).
function(step_build_framework)
  build(raylab_framework raylab_grader)
endfunction()

# 3. The README's first command builds the figures alone (raylab, no grading program): `raylab grade`
# then builds the grading programs first.
function(step_build_figures)
  build(figures)
  if(EXISTS ${build}/bin/raylab-agent)
    message(FATAL_ERROR "students' tree: building the figures built the grading programs too")
  endif()
endfunction()
function(step_grade_builds)
  run(output 3 ${build}/bin/raylab --lang en grade --lab 1)
  expect("${output}" "building the grading programs first" "raylab grade after the figures' build")
  if(NOT EXISTS ${build}/bin/raylab-agent)
    message(FATAL_ERROR "students' tree: raylab grade did not build its grading programs")
  endif()
endfunction()

# 4. The rest of the tree (its tests), then its suite with no lab written.
function(step_build_suite)
  build(all)
endfunction()
function(step_suite_none)
  suite_passes("")
endfunction()

# The instructors' commands whose code holds a lab's answer are not built here, and say so.
function(step_instructors_commands)
  foreach(command "numerics" "study;intersection")
    run(output 1 ${build}/bin/raylab ${command})
    expect("${output}" "is an instructors' command" "raylab ${command}")
  endforeach()
endfunction()

# A student's lab: the solution's files written over the stubs (anew, so they are newer than the build).
function(write_lab folder)
  file(GLOB files ${SOLUTIONS}/${folder}/*.cpp)
  foreach(file IN LISTS files)
    get_filename_component(name ${file} NAME)
    file(READ ${file} text)
    file(WRITE ${tree}/labs/${folder}/${name} "${text}")
  endforeach()
endfunction()

# 5. Lab 1 written, then every lab of the tree.
function(step_suite_lab1)
  write_lab(lab1_first_image)
  suite_passes("1")
endfunction()
# 6. A lab that does not compile costs that lab alone: its first file loses a `;`. The course's first
# lab (written) keeps its points, `raylab lab` still draws its pictures from the student's code (the tool
# is built with the broken lab's stub), and the broken lab's pictures say why they are not drawn. Then
# the file mended, every lab's code is built again.
function(step_broken_lab)
  tree_labs(folders numbers)
  list(GET folders 0 written)
  list(GET numbers 0 written_number)
  list(GET folders -1 broken)
  list(GET numbers -1 broken_number)
  if(broken STREQUAL written)
    message(STATUS "students' tree: one lab only, no other lab to keep")
    return()
  endif()
  file(GLOB files ${tree}/labs/${broken}/*.cpp)
  list(GET files 0 file)
  file(READ ${file} before)
  file(APPEND ${file} "\nint raylab_missing_semicolon = 1\n")
  run(output 1 ${build}/bin/raylab --lang en grade)
  expect("${output}" "lab ${written_number}: " "the written lab graded")
  string(REGEX MATCH "lab ${written_number}: ([0-9.]+) / ([0-9.]+)" points "${output}")
  if(NOT CMAKE_MATCH_1 STREQUAL CMAKE_MATCH_2)
    message(FATAL_ERROR "students' tree: lab ${written_number} lost points to lab ${broken_number}'s compile error:\n${output}")
  endif()
  expect("${output}" "the code does not build" "lab ${broken_number} graded as not compiling")
  expect("${output}" "raylab_missing_semicolon" "the compiler's error in the grade")
  run(output 0 ${build}/bin/raylab --lang en lab ${written_number})
  expect("${output}" "-> out/student/lab${written_number}_" "lab ${written_number}'s pictures drawn")
  run(output 1 ${build}/bin/raylab --lang en lab ${broken_number})
  expect("${output}" "lab ${broken_number} does not compile" "lab ${broken_number}'s pictures")
  file(WRITE ${file} "${before}")
  run(output 0 ${build}/bin/raylab --lang en lab ${written_number})
  expect("${output}" "every lab compiles again" "the mended lab")
endfunction()

# 7. One build at a time: two `raylab grade` started together after an edit (a pipeline: both run at
# once) both grade, and the programs are whole after them. The first one's output goes to the second,
# which does not read it and may end first: the first grades all the same (no SIGPIPE death).
function(step_two_at_once)
  tree_labs(folders numbers)
  list(GET folders 0 written)
  list(GET numbers 0 written_number)
  file(GLOB files ${tree}/labs/${written}/*.cpp)
  list(GET files 0 file)
  file(APPEND ${file} "\nnamespace { [[maybe_unused]] const int raylab_two_at_once = 2; }\n")
  execute_process(COMMAND ${build}/bin/raylab --lang en grade --lab ${written_number}
                  COMMAND ${build}/bin/raylab --lang en grade --lab ${written_number}
                  WORKING_DIRECTORY ${tree} RESULTS_VARIABLE statuses OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message(STATUS "students' tree: two `raylab grade` at once -> ${statuses}")
  if(NOT statuses STREQUAL "0;0")
    message(FATAL_ERROR "students' tree: two `raylab grade` at once exited with ${statuses}:\n${out}${err}")
  endif()
  run(output 0 ${build}/bin/raylab --lang en grade --lab ${written_number})
  expect("${output}" "lab ${written_number}: " "a grade after both")
endfunction()

function(step_suite_all)
  tree_labs(folders numbers)
  foreach(folder IN LISTS folders)
    write_lab(${folder})
  endforeach()
  suite_passes("${numbers}")
  list(LENGTH numbers count)
  message(STATUS "students' tree: its suite passes with 0, 1 and all ${count} labs written")
endfunction()

# 6. A student's own correct labs, written from the handouts and not from solutions/ (VARIANT: the
# folder where the repository's build applied tests/instructors/variants/independent_student.patch; lab 1 and
# any file it leaves from solutions/): every point in the tree's self-grade, where each lab runs over
# the student's own earlier labs, and the same points, lab by lab, as the instructor's `grade-class`
# of the same files, where each lab runs over the references of the others (docs/grading.md,
# "Deterministic figures": rays a rounding apart upstream do not cost a lab its points).
function(step_variants)
  if(NOT VARIANT OR NOT IS_DIRECTORY ${VARIANT})
    message(FATAL_ERROR "students' tree: -DVARIANT=<the applied independent_student variant> is required")
  endif()
  tree_labs(folders numbers)
  foreach(folder IN LISTS folders)
    write_lab(${folder})
    file(GLOB files ${VARIANT}/${folder}/*.cpp)
    foreach(file IN LISTS files)
      get_filename_component(name ${file} NAME)
      file(READ ${file} text)
      file(WRITE ${tree}/labs/${folder}/${name} "${text}")
    endforeach()
  endforeach()
  run(self 0 ${build}/bin/raylab --lang en grade)
  set(class ${WORK}/variant-class)
  file(REMOVE_RECURSE ${class})
  file(MAKE_DIRECTORY ${class}/student)
  file(COPY ${tree}/labs DESTINATION ${class}/student)
  # The test's own code: no sandbox needed (grade-class refuses to run without one where bubblewrap
  # cannot start otherwise), and none changes a point.
  run(output 0 ${RAYLAB} --lang en grade-class ${class} --out ${WORK}/variant-class-out --no-sandbox)
  file(STRINGS ${WORK}/variant-class-out/grades.csv rows)
  list(GET rows 0 header)
  list(GET rows 1 row)
  string(REPLACE "," ";" header "${header}")
  string(REPLACE "," ";" row "${row}")
  foreach(n IN LISTS numbers)
    string(REGEX MATCH "lab ${n}: ([0-9.]+) / ([0-9.]+) point" said "${self}")
    if(NOT said)
      message(FATAL_ERROR "students' tree: no points of lab ${n} in the self-grade:\n${self}")
    endif()
    set(points ${CMAKE_MATCH_1})
    if(NOT points STREQUAL CMAKE_MATCH_2)
      message(FATAL_ERROR "students' tree: a student's own correct labs: lab ${n} ${points} / ${CMAKE_MATCH_2} in the self-grade:\n${self}")
    endif()
    list(FIND header "lab${n}" column)
    if(column EQUAL -1)
      message(FATAL_ERROR "students' tree: no column lab${n} in grades.csv: ${header}")
    endif()
    list(GET row ${column} graded)
    if(NOT graded STREQUAL points)
      message(FATAL_ERROR "students' tree: lab ${n}: ${points} points in the self-grade, ${graded} by grade-class:\n${self}\n${output}")
    endif()
  endforeach()
  message(STATUS "students' tree: a student's own correct labs get every point, the same as grade-class gives them")
endfunction()

run_step()
