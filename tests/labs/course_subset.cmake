# A course that hands out fewer labs: in a copy of the tree whose course.toml leaves out its first lab,
# CMake builds the others only, the figures and the grade are theirs alone, and `raylab distribute`
# writes a students' tree without the left-out lab's folders (absent, not a zero). The labs are
# whichever the tree has: the test reads labs/, never a list of its own.
# The first lab, because a lab whose functions the framework itself calls (a member of the camera, the
# sphere, the integrator or the renderer: labs 2 to 5 today) cannot be left out yet: nothing else
# would define them, and the programs do not link (docs/instructors.md, "Adding a lab").
#
#   cmake -DSTEP=<step> -DSOURCE=<tree> -DWORK=<scratch folder> [-DGENERATOR=Ninja] [-DCCACHE=<ccache>]
#         -P tests/labs/course_subset.cmake
# Steps (one ctest test each, in the tree the steps before left): copy, build, figures, grade, distribute.

foreach(var STEP SOURCE WORK)
  if(NOT ${var})
    message(FATAL_ERROR "course subset: -D${var}=... is required")
  endif()
endforeach()
set(tree ${WORK}/tree)
set(build ${tree}/build) # inside the tree, as build/ is: the compiler cache sees the same paths
set(bin ${build}/bin)
set(STEP_PREFIX "course subset")
include(${CMAKE_CURRENT_LIST_DIR}/script_steps.cmake)

# The labs of the source tree by number; the course leaves out the first.
file(GLOB lab_files RELATIVE ${SOURCE}/labs ${SOURCE}/labs/lab*/lab.toml)
set(numbers "")
foreach(file IN LISTS lab_files)
  if(file MATCHES "^lab([0-9]+)_([^/]*)/")
    list(APPEND numbers ${CMAKE_MATCH_1})
    set(folder_${CMAKE_MATCH_1} lab${CMAKE_MATCH_1}_${CMAKE_MATCH_2})
  endif()
endforeach()
list(SORT numbers COMPARE NATURAL)
list(LENGTH numbers count)
if(count LESS 2)
  message(FATAL_ERROR "course subset: the tree has ${count} lab; a course needs one")
endif()
list(SUBLIST numbers 0 1 left_out)
list(SUBLIST numbers 1 -1 kept)
string(REPLACE ";" ", " kept_list "${kept}")

# The figure ids of a left-out lab (its scene files' names).
function(left_out_figures out)
  set(ids "")
  foreach(n IN LISTS left_out)
    file(GLOB scenes ${SOURCE}/labs/${folder_${n}}/scenes/*.toml)
    foreach(scene IN LISTS scenes)
      get_filename_component(id ${scene} NAME_WE)
      list(APPEND ids ${id})
    endforeach()
  endforeach()
  set(${out} ${ids} PARENT_SCOPE)
endfunction()

# Fails when TEXT names a lab left out ("lab N:") or one of its figures.
function(expect_none_left_out text what)
  left_out_figures(ids)
  foreach(n IN LISTS left_out)
    string(FIND "${text}" "lab ${n}:" at)
    if(NOT at EQUAL -1)
      message(FATAL_ERROR "course subset: ${what} names lab ${n}, which the course leaves out:\n${text}")
    endif()
  endforeach()
  foreach(id IN LISTS ids)
    string(FIND "${text}" "${id}" at)
    if(NOT at EQUAL -1)
      message(FATAL_ERROR "course subset: ${what} names ${id}, a figure of a lab the course leaves out:\n${text}")
    endif()
  endforeach()
endfunction()

# 1. The copy (no tests/: the programs only), its course.toml without the first lab, configured.
function(step_copy)
  file(REMOVE_RECURSE ${WORK})
  file(MAKE_DIRECTORY ${tree})
  foreach(part framework labs solutions scenes cmake)
    file(COPY ${SOURCE}/${part} DESTINATION ${tree})
  endforeach()
  file(COPY ${SOURCE}/CMakeLists.txt ${SOURCE}/CMakePresets.json DESTINATION ${tree})
  file(WRITE ${tree}/course.toml "# A course without its first lab (tests/labs/course_subset.cmake).\nlabs = [${kept_list}]\n")
  set(configure ${CMAKE_COMMAND} -S ${tree} -B ${build} -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF -DRAYLAB_LTO=OFF)
  if(GENERATOR)
    list(APPEND configure -G ${GENERATOR})
  endif()
  if(CCACHE)
    list(APPEND configure -DCMAKE_CXX_COMPILER_LAUNCHER=${CCACHE})
  endif()
  run(output 0 ${configure})
  set(folders "")
  foreach(n IN LISTS kept)
    list(APPEND folders ${folder_${n}})
  endforeach()
  expect("${output}" "raylab labs: ${folders}\n" "CMake builds the course's labs only")
endfunction()

function(step_build)
  build(raylab raylab-reference raylab-agents)
  foreach(n IN LISTS left_out)
    if(EXISTS ${bin}/raylab-agent-lab${n})
      message(FATAL_ERROR "course subset: an agent of lab ${n}, which the course leaves out, was built")
    endif()
  endforeach()
endfunction()

# 2. The figures are the course's labs'.
function(step_figures)
  run(output 0 ${bin}/raylab-reference figures --out ${WORK}/figures)
  expect_none_left_out("${output}" "raylab-reference figures")
endfunction()

# 3. The reference gets every point of the course's labs, the others are not graded at all.
function(step_grade)
  run(output 0 ${bin}/raylab grade --agent ${bin}/raylab-agent-reference --report ${WORK}/grade)
  foreach(n IN LISTS kept)
    expect("${output}" "lab ${n}: " "lab ${n} is graded")
  endforeach()
  expect_none_left_out("${output}" "raylab grade")
  file(READ ${WORK}/grade/results.json results)
  expect_none_left_out("${results}" "results.json")
endfunction()

# 4. The students' tree has the course's labs only, and its course.toml.
function(step_distribute)
  run(output 0 ${bin}/raylab distribute ${WORK}/students)
  foreach(n IN LISTS kept)
    if(NOT EXISTS ${WORK}/students/labs/${folder_${n}}/lab.toml)
      message(FATAL_ERROR "course subset: the students' tree lacks lab ${n}")
    endif()
  endforeach()
  foreach(n IN LISTS left_out)
    foreach(where labs framework/grader/labs)
      if(EXISTS ${WORK}/students/${where}/${folder_${n}})
        message(FATAL_ERROR "course subset: the students' tree has ${where}/${folder_${n}}, which the course leaves out")
      endif()
    endforeach()
  endforeach()
  file(READ ${WORK}/students/course.toml course)
  expect("${course}" "labs = [${kept_list}]" "the students' tree has the course's list")
  message(STATUS "course subset: labs ${kept_list} built, drawn, graded and handed out; ${left_out} left out")
endfunction()

run_step()
