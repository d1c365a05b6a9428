# Each lab folder is a small object library, built once from labs/ (the student's code) and once
# from solutions/ (the reference), when solutions/ is there. A program links one of each lab:
# which one comes from where is a list of the labs taken from solutions/.
#
# The labs are found, not listed: every labs/lab<N>_<name>/lab.toml is lab N, whose id is its
# folder's name; those of the course's list (course.toml) are built. Sets RAYLAB_LAB_NUMBERS (the
# course's, sorted), RAYLAB_LAB_FOLDER_<n> and RAYLAB_LABS (their folders, in the order of their numbers).
# A lab the course leaves out whose functions the framework itself calls (lab.toml's `framework_calls =
# true`: members of framework classes) is given: every program links its reference, as part of the
# framework, and nothing grades it. RAYLAB_GIVEN_LAB_NUMBERS lists them. Its reference is solutions/<lab>/
# where the tree has it, else framework/given/<lab>/, which `raylab distribute` writes for a students'
# tree (there each folder of framework/given/ is a given lab: its lab.toml is not handed out).

#
# The reference labs are solutions/<lab folder>/*.cpp, or, in Gradescope's image, the objects compiled
# from them (*.o in the same folders: the zip's setup.sh builds them once, with the target
# raylab-reference-objects, and deletes the sources). RAYLAB_HAVE_SOLUTIONS: the sources are here;
# RAYLAB_HAVE_REFERENCE_LABS: the sources or their objects, enough to grade each lab on its own.
file(GLOB raylab_solution_sources ${CMAKE_SOURCE_DIR}/solutions/lab*/*.cpp)
file(GLOB raylab_solution_objects ${CMAKE_SOURCE_DIR}/solutions/lab*/*${CMAKE_CXX_OUTPUT_EXTENSION})
if(raylab_solution_sources)
  set(RAYLAB_HAVE_SOLUTIONS ON)
else()
  set(RAYLAB_HAVE_SOLUTIONS OFF)
endif()
if(raylab_solution_sources OR raylab_solution_objects)
  set(RAYLAB_HAVE_REFERENCE_LABS ON)
else()
  set(RAYLAB_HAVE_REFERENCE_LABS OFF)
endif()

# raylab_course_labs(OUT FOUND...): the labs of the course's list (course.toml at the top of the tree,
# `labs = [1, 2, 3]`; read by the grader too, grader/course_list.cpp), each of which must be FOUND;
# every lab found when the tree has no course.toml. CMake cannot parse TOML: the list is one line.
function(raylab_course_labs out)
  set(found ${ARGN})
  set(file ${CMAKE_SOURCE_DIR}/course.toml)
  if(NOT EXISTS ${file})
    set(${out} ${found} PARENT_SCOPE)
    return()
  endif()
  set_property(DIRECTORY ${CMAKE_SOURCE_DIR} APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${file})
  file(STRINGS ${file} lines REGEX "^[ \t]*labs[ \t]*=")
  list(LENGTH lines count)
  if(NOT count EQUAL 1 OR NOT lines MATCHES "^[ \t]*labs[ \t]*=[ \t]*\\[([0-9, \t]*)\\][ \t]*(#.*)?$")
    message(FATAL_ERROR "${file}: expected one line `labs = [1, 2, 3]` (the numbers of the labs the course hands out)")
  endif()
  string(REGEX MATCHALL "[0-9]+" listed "${CMAKE_MATCH_1}")
  if(NOT listed)
    message(FATAL_ERROR "${file}: labs: the list is empty (a course hands out at least one lab)")
  endif()
  foreach(n IN LISTS listed)
    if(NOT n IN_LIST found)
      message(FATAL_ERROR "${file}: labs: there is no lab ${n} (labs/lab${n}_<name>/lab.toml; the labs found are ${found})")
    endif()
  endforeach()
  set(${out} ${listed} PARENT_SCOPE)
endfunction()

# raylab_heading_value(OUT FILE KEY VALUE EXAMPLE): the value of KEY in lab.toml FILE, a key of its
# heading (before its first [table]) on one line, as the regular expression VALUE's first group
# matches it; empty when the key is absent. CMake cannot parse TOML: the grader's catalogue reads the
# same keys strictly. A line VALUE does not match stops the configuration, showing EXAMPLE.
function(raylab_heading_value out file key value example)
  file(STRINGS ${file} lines REGEX "^[ \t]*(${key}[ \t]*=|\\[)")
  set(found "")
  foreach(line IN LISTS lines)
    if(line MATCHES "^[ \t]*\\[")
      break()
    endif()
    if(NOT line MATCHES "^[ \t]*${key}[ \t]*=[ \t]*${value}[ \t]*(#.*)?$")
      message(FATAL_ERROR "${file}: expected one line ${example}: ${line}")
    endif()
    set(found "${CMAKE_MATCH_1}")
  endforeach()
  set(${out} "${found}" PARENT_SCOPE)
endfunction()

# raylab_framework_calls(OUT FILE): whether lab.toml FILE says `framework_calls = true`.
function(raylab_framework_calls out file)
  set_property(DIRECTORY ${CMAKE_SOURCE_DIR} APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${file})
  raylab_heading_value(value ${file} framework_calls "(true|false)" "`framework_calls = true` (or false)")
  if(value STREQUAL "true")
    set(${out} ON PARENT_SCOPE)
  else()
    set(${out} OFF PARENT_SCOPE)
  endif()
endfunction()

# raylab_lab_uses(OUT FILE): the labs that lab.toml FILE says its lab uses (`uses = [2, 3]`). A lab's
# own agent in a tree without the reference links these labs' code from labs/ (framework/grader/).
function(raylab_lab_uses out file)
  raylab_heading_value(value ${file} uses "\\[([0-9, \t]*)\\]"
                       "`uses = [2, 3]` (the labs whose code this lab's figures run)")
  string(REGEX MATCHALL "[0-9]+" uses "${value}")
  set(${out} ${uses} PARENT_SCOPE)
endfunction()

# raylab_lab_kinds(OUT FILE ROLE): the kinds of objects (ROLE shapes) or of lights (ROLE lights)
# lab.toml FILE says its lab brings (`shapes = ["Triangle"]`): classes its folder's <ROLE>.h declares.
function(raylab_lab_kinds out file role)
  raylab_heading_value(value ${file} ${role} "\\[([A-Za-z0-9_\", \t]*)\\]"
                       "`${role} = [\"ClassName\"]` (the classes of its ${role}.h)")
  string(REGEX MATCHALL "[A-Za-z_][A-Za-z0-9_]*" classes "${value}")
  set(${out} ${classes} PARENT_SCOPE)
endfunction()

# A lab's number and id come from its folder's name, lab<N>_<name> (N without a leading zero), not
# from lab.toml, which CMake cannot parse; the grader's catalogue (framework/grader/lab_catalog.cpp)
# checks that lab.toml's `number` and `id` say the same.
file(GLOB raylab_lab_files CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/labs/lab*/lab.toml)
set(RAYLAB_LAB_NUMBERS "")
foreach(file IN LISTS raylab_lab_files)
  get_filename_component(folder_path ${file} DIRECTORY)
  get_filename_component(folder ${folder_path} NAME)
  if(NOT folder MATCHES "^lab([1-9][0-9]*)_.")
    message(FATAL_ERROR "${file}: the folder ${folder} is not named lab<number>_<name>, the number without a leading zero (see docs/instructors.md)")
  endif()
  set(number ${CMAKE_MATCH_1})
  if(number IN_LIST RAYLAB_LAB_NUMBERS)
    message(FATAL_ERROR "${file}: the folders ${RAYLAB_LAB_FOLDER_${number}} and ${folder} both have the number ${number} (one lab a number)")
  endif()
  list(APPEND RAYLAB_LAB_NUMBERS ${number})
  set(RAYLAB_LAB_FOLDER_${number} ${folder})
  raylab_framework_calls(RAYLAB_LAB_FRAMEWORK_CALLS_${number} ${file})
  if(NOT DEFINED RAYLAB_LAB_USES_${number}) # the grader gives them when it configures a submission's build
    raylab_lab_uses(RAYLAB_LAB_DECLARED_USES_${number} ${file})
  else()
    set(RAYLAB_LAB_DECLARED_USES_${number} ${RAYLAB_LAB_USES_${number}})
  endif()
endforeach()
set(raylab_found_labs ${RAYLAB_LAB_NUMBERS})
if(NOT RAYLAB_LAB_NUMBERS)
  message(FATAL_ERROR "no lab: there is no labs/lab*/lab.toml")
endif()
raylab_course_labs(RAYLAB_LAB_NUMBERS ${RAYLAB_LAB_NUMBERS})
list(SORT RAYLAB_LAB_NUMBERS COMPARE NATURAL)
set(RAYLAB_LABS "")
foreach(n IN LISTS RAYLAB_LAB_NUMBERS)
  list(APPEND RAYLAB_LABS ${RAYLAB_LAB_FOLDER_${n}})
endforeach()
message(STATUS "raylab labs: ${RAYLAB_LABS}")
set(RAYLAB_GIVEN_LAB_NUMBERS "")
foreach(n IN LISTS raylab_found_labs)
  if(RAYLAB_LAB_FRAMEWORK_CALLS_${n} AND NOT n IN_LIST RAYLAB_LAB_NUMBERS)
    list(APPEND RAYLAB_GIVEN_LAB_NUMBERS ${n})
  endif()
endforeach()
# A students' tree has no lab.toml of a given lab, only its reference (raylab distribute).
file(GLOB given_paths LIST_DIRECTORIES true ${CMAKE_SOURCE_DIR}/framework/given/lab*)
foreach(path IN LISTS given_paths)
  get_filename_component(folder ${path} NAME)
  if(IS_DIRECTORY ${path} AND folder MATCHES "^lab([1-9][0-9]*)_.")
    set(n ${CMAKE_MATCH_1})
    if(NOT DEFINED RAYLAB_LAB_FOLDER_${n})
      set(RAYLAB_LAB_FOLDER_${n} ${folder})
      list(APPEND RAYLAB_GIVEN_LAB_NUMBERS ${n})
    endif()
  endif()
endforeach()
list(SORT RAYLAB_GIVEN_LAB_NUMBERS COMPARE NATURAL)
set(given_folders "")
foreach(n IN LISTS RAYLAB_GIVEN_LAB_NUMBERS)
  list(APPEND given_folders ${RAYLAB_LAB_FOLDER_${n}})
endforeach()
if(given_folders)
  message(STATUS "raylab labs given (their reference, part of the framework): ${given_folders}")
endif()

# raylab_lab_header_folder(OUT N): the folder of lab N's own header, labs/<lab>/<name>.h (it declares the
# functions a student writes that no framework class declares: the stub, the solution and the lab's
# grading folder include it); a given lab's in a students' tree is framework/given/<lab>/.
function(raylab_lab_header_folder out n)
  set(folder ${RAYLAB_LAB_FOLDER_${n}})
  if(n IN_LIST RAYLAB_GIVEN_LAB_NUMBERS AND NOT EXISTS ${CMAKE_SOURCE_DIR}/labs/${folder})
    set(${out} ${CMAKE_SOURCE_DIR}/framework/given/${folder} PARENT_SCOPE)
  else()
    set(${out} ${CMAKE_SOURCE_DIR}/labs/${folder} PARENT_SCOPE)
  endif()
endfunction()

# The kinds of objects the course's labs and the given labs bring, after the framework's sphere and
# plane, and the kinds of lights, after the point light: Scene (raylab/scene.h) keeps one array per
# kind and tests each kind of object inline, so it knows the lists when it is compiled. A given lab's
# kinds are the framework's like the rest of it: a later lab's scenes use them (a BVH lab over an
# earlier lab's triangles). Written into raylab/course_kinds.h only when it changes: a configure
# recompiles nothing.
set(raylab_kind_includes "")
foreach(role shapes lights)
  set(raylab_course_${role} "")
  foreach(n IN LISTS RAYLAB_LAB_NUMBERS RAYLAB_GIVEN_LAB_NUMBERS)
    set(folder ${RAYLAB_LAB_FOLDER_${n}})
    raylab_lab_header_folder(header_folder ${n})
    # A given lab's lab.toml is beside its header in a students' tree (raylab distribute).
    set(description ${CMAKE_SOURCE_DIR}/labs/${folder}/lab.toml)
    if(NOT EXISTS ${description})
      set(description ${header_folder}/lab.toml)
    endif()
    raylab_lab_kinds(classes ${description} ${role})
    if(classes)
      if(NOT EXISTS ${header_folder}/${role}.h)
        message(FATAL_ERROR "${description}: ${role} = ${classes}, but ${header_folder}/${role}.h, which declares them, is not there")
      endif()
      string(APPEND raylab_kind_includes "#include \"${folder}/${role}.h\"\n")
      foreach(class IN LISTS classes)
        string(APPEND raylab_course_${role} ", ::raylab::${class}")
      endforeach()
    endif()
  endforeach()
endforeach()
set(RAYLAB_COURSE_KINDS_FOLDER ${CMAKE_BINARY_DIR}/generated/course)
file(CONFIGURE OUTPUT ${RAYLAB_COURSE_KINDS_FOLDER}/raylab/course_kinds.h CONTENT
"#pragma once
// Written by CMake (cmake/RaylabLabs.cmake): the kinds of objects and of lights the course's labs
// bring, from their lab.toml's `shapes` and `lights`, for Scene (raylab/scene.h).
${raylab_kind_includes}
#define RAYLAB_COURSE_SHAPES ${raylab_course_shapes}
#define RAYLAB_COURSE_LIGHTS ${raylab_course_lights}
")

# raylab_lab_shadings(TARGET N): TARGET (lab N's code, from wherever) also brings what lab N registers
# by name outside the student's files, from framework/grader/labs/<lab>/: shadings.cpp, the pictures
# (lab 1's gradient, lab 2's directions, lab 3's shadings; a scene file's [render] shading names one),
# shapes.cpp and lights.cpp, its kinds of objects and lights (a scene file's [[table]] names one:
# raylab/kind_registry.h),
# and figure_steps.cpp, its functions as the crash finder calls them (src/figure_steps.h). Compiled
# once, into every program that links TARGET: nothing names their objects, so they are linked whole.
function(raylab_lab_shadings target n)
  set(sources "")
  foreach(part shadings shapes lights figure_steps)
    set(source ${CMAKE_SOURCE_DIR}/framework/grader/labs/${RAYLAB_LAB_FOLDER_${n}}/${part}.cpp)
    if(EXISTS ${source})
      list(APPEND sources ${source})
    endif()
  endforeach()
  if(NOT sources)
    return()
  endif()
  set(shadings raylab_lab${n}_shadings)
  if(NOT TARGET ${shadings})
    add_library(${shadings} OBJECT ${sources})
    target_link_libraries(${shadings} PRIVATE raylab_framework raylab_internals raylab_warnings)
    raylab_lab_header_folder(header_folder ${n})
    target_include_directories(${shadings} PRIVATE ${header_folder})
    # Its lab, for RAYLAB_REGISTER_FIGURE_STEP: the grading folder's name.
    target_compile_definitions(${shadings} PRIVATE RAYLAB_LAB_ID="${RAYLAB_LAB_FOLDER_${n}}")
  endif()
  target_link_libraries(${target} INTERFACE $<TARGET_OBJECTS:${shadings}>)
  get_target_property(imported ${target} IMPORTED)
  if(NOT imported) # built before whatever links TARGET
    add_dependencies(${target} ${shadings})
  endif()
endfunction()

# raylab_lab_target(OUT N ORIGIN): the object library of lab N from ORIGIN: labs, solutions, given (a
# given lab's reference: solutions/ where the tree has it, else framework/given/), or stubs (the lab as
# handed out, whatever the student wrote since: framework/stubs/, which `raylab distribute` writes for
# a students' tree, else labs/, which are the stubs in the instructors' tree).
function(raylab_lab_target out n origin)
  set(folder ${RAYLAB_LAB_FOLDER_${n}})
  if(NOT folder)
    message(FATAL_ERROR "there is no lab ${n} (the labs are ${RAYLAB_LAB_NUMBERS})")
  endif()
  set(dir ${origin}/${folder})
  if(origin STREQUAL "stubs")
    if(NOT IS_DIRECTORY ${CMAKE_SOURCE_DIR}/framework/stubs/${folder})
      raylab_lab_target(target ${n} labs)
      set(${out} ${target} PARENT_SCOPE)
      return()
    endif()
    set(dir framework/stubs/${folder})
  endif()
  if(origin STREQUAL "given")
    file(GLOB reference ${CMAKE_SOURCE_DIR}/solutions/${folder}/*)
    if(reference)
      raylab_lab_target(target ${n} solutions)
      set(${out} ${target} PARENT_SCOPE)
      return()
    endif()
    set(dir framework/given/${folder})
  endif()
  raylab_lab_header_folder(header_folder ${n})
  set(target raylab_lab${n}_${origin})
  if(NOT TARGET ${target})
    file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/${dir}/*.cpp)
    file(GLOB objects ${CMAKE_SOURCE_DIR}/${dir}/*${CMAKE_CXX_OUTPUT_EXTENSION})
    if(NOT sources AND objects AND origin STREQUAL "solutions")
      # The reference compiled by the zip's setup.sh, its sources deleted.
      add_library(${target} OBJECT IMPORTED GLOBAL)
      set_target_properties(${target} PROPERTIES IMPORTED_OBJECTS "${objects}")
      target_link_libraries(${target} INTERFACE raylab_framework)
      target_include_directories(${target} INTERFACE ${header_folder})
      raylab_lab_shadings(${target} ${n})
      set(${out} ${target} PARENT_SCOPE)
      return()
    endif()
    if(NOT sources)
      message(FATAL_ERROR "${dir} has no .cpp file")
    endif()
    add_library(${target} OBJECT ${sources})
    target_link_libraries(${target} PUBLIC raylab_framework PRIVATE raylab_warnings)
    target_include_directories(${target} PUBLIC ${header_folder}) # the lab's own header
    raylab_lab_shadings(${target} ${n})
    if(origin MATCHES "^(labs|stubs)$")
      # A stub's one-line body ignores its parameters on purpose. On the sources, not the target: their
      # options come after raylab_warnings' -Wextra, which would turn the warning on again (Clang).
      set_property(SOURCE ${sources} APPEND PROPERTY COMPILE_OPTIONS $<$<NOT:$<CXX_COMPILER_ID:MSVC>>:-Wno-unused-parameter>)
    endif()
  endif()
  set(${out} ${target} PARENT_SCOPE)
endfunction()

# raylab_link_given_labs(TARGET): links the given labs' reference (none when the course hands out every
# lab the framework calls).
function(raylab_link_given_labs target)
  foreach(n IN LISTS RAYLAB_GIVEN_LAB_NUMBERS)
    raylab_lab_target(lab ${n} given)
    target_link_libraries(${target} PRIVATE ${lab})
  endforeach()
endfunction()

# raylab_link_labs(TARGET REFERENCE_LABS): links every lab, those listed from solutions/, those of
# RAYLAB_STUB_LABS from their stubs, and the given labs.
# Sets RAYLAB_LAB_ORIGINS on the target's compile definitions ("lab1=labs lab2=solutions lab5=given ...").
function(raylab_link_labs target)
  set(reference_labs ${ARGN})
  set(origins "")
  foreach(n IN LISTS RAYLAB_LAB_NUMBERS)
    if(n IN_LIST reference_labs)
      if(NOT RAYLAB_HAVE_REFERENCE_LABS)
        message(FATAL_ERROR "${target}: lab ${n} is asked from solutions/, but this tree has no solutions/")
      endif()
      set(origin solutions)
    elseif(n IN_LIST RAYLAB_STUB_LABS)
      set(origin stubs)
    else()
      set(origin labs)
    endif()
    raylab_lab_target(lab ${n} ${origin})
    target_link_libraries(${target} PRIVATE ${lab})
    string(APPEND origins "lab${n}=${origin} ")
  endforeach()
  raylab_link_given_labs(${target})
  foreach(n IN LISTS RAYLAB_GIVEN_LAB_NUMBERS)
    string(APPEND origins "lab${n}=given ")
  endforeach()
  string(STRIP "${origins}" origins)
  target_link_libraries(${target} PRIVATE raylab_framework)
  target_compile_definitions(${target} PRIVATE RAYLAB_LAB_ORIGINS="${origins}")
endfunction()

# raylab_add_reference_objects_target(): `raylab-reference-objects` copies the compiled reference labs
# beside their sources (solutions/<lab folder>/*.o), for the zip's setup.sh, which then deletes the
# sources: the students' labs are graded each with the others' reference, which they cannot read.
function(raylab_add_reference_objects_target)
  set(commands "")
  set(targets "")
  foreach(n IN LISTS RAYLAB_LAB_NUMBERS)
    set(target raylab_lab${n}_solutions)
    if(TARGET ${target})
      get_target_property(imported ${target} IMPORTED)
      if(NOT imported)
        list(APPEND commands COMMAND ${CMAKE_COMMAND} -E copy $<TARGET_OBJECTS:${target}>
             ${CMAKE_SOURCE_DIR}/solutions/${RAYLAB_LAB_FOLDER_${n}}/)
        list(APPEND targets ${target})
      endif()
    endif()
  endforeach()
  if(targets)
    add_custom_target(raylab-reference-objects ${commands} COMMAND_EXPAND_LISTS VERBATIM)
    add_dependencies(raylab-reference-objects ${targets})
  endif()
endfunction()
