# Each lab folder is a small object library, built once from labs/ (the student's code) and once
# from solutions/ (the reference), when solutions/ is there. A program links one of each lab:
# which one comes from where is a list of the labs taken from solutions/.

set(RAYLAB_LABS lab1_first_image lab2_primary_rays lab3_sphere lab4_lookat_camera lab5_antialiasing)
if(EXISTS ${CMAKE_SOURCE_DIR}/solutions)
  set(RAYLAB_HAVE_SOLUTIONS ON)
else()
  set(RAYLAB_HAVE_SOLUTIONS OFF)
endif()

# raylab_lab_target(OUT N ORIGIN): the object library of lab N (1..5) from ORIGIN (labs or solutions).
function(raylab_lab_target out n origin)
  math(EXPR index "${n} - 1")
  list(GET RAYLAB_LABS ${index} folder)
  set(target raylab_lab${n}_${origin})
  if(NOT TARGET ${target})
    file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/${origin}/${folder}/*.cpp)
    add_library(${target} OBJECT ${sources})
    target_link_libraries(${target} PUBLIC raylab_framework PRIVATE raylab_warnings)
    if(origin STREQUAL "labs")
      # A stub's one-line body ignores its parameters on purpose.
      target_compile_options(${target} PRIVATE $<$<NOT:$<CXX_COMPILER_ID:MSVC>>:-Wno-unused-parameter>)
    endif()
  endif()
  set(${out} ${target} PARENT_SCOPE)
endfunction()

# raylab_link_labs(TARGET REFERENCE_LABS): links the five labs, those listed from solutions/.
# Sets RAYLAB_LAB_ORIGINS on the target's compile definitions ("lab1=labs lab2=solutions ...").
function(raylab_link_labs target)
  set(reference_labs ${ARGN})
  set(origins "")
  foreach(n RANGE 1 5)
    if(n IN_LIST reference_labs)
      if(NOT RAYLAB_HAVE_SOLUTIONS)
        message(FATAL_ERROR "${target}: lab ${n} is asked from solutions/, but this tree has no solutions/")
      endif()
      set(origin solutions)
    else()
      set(origin labs)
    endif()
    raylab_lab_target(lab ${n} ${origin})
    target_link_libraries(${target} PRIVATE ${lab})
    string(APPEND origins "lab${n}=${origin} ")
  endforeach()
  string(STRIP "${origins}" origins)
  target_link_libraries(${target} PRIVATE raylab_framework)
  target_compile_definitions(${target} PRIVATE RAYLAB_LAB_ORIGINS="${origins}")
endfunction()
