# The compiler cache of the trees the slow tests build: the toy lab's and the students' (tests/labs),
# the Gradescope zip's setup.sh (tests/autograder). Each is a copy of this tree with its build folder
# inside, as build/ is here, so that with CCACHE_BASEDIR a file of the framework, the grader or the
# command-line tool compiles with the same command in every tree (relative paths).
#
# When ccache is installed the trees compile through a cache of their own, whatever the user's
# settings (CCACHE_DISABLE too): RAYLAB_TREES_CCACHE_DIR, from the environment variable of that name
# when set (CI keeps it between runs), else build/trees-ccache. Where those tests are (solutions/
# is here), this build compiles through it too, unless the user set a compiler launcher: then the
# trees find in it what this build compiled and compile only what differs in them (the toy lab's
# sixth lab, the students' tree's missing solutions). Without ccache each tree compiles everything.
#
# Sets RAYLAB_CCACHE (empty without ccache) and RAYLAB_TREES_CCACHE_ENVIRONMENT (the settings a
# tree's build runs with).
find_program(RAYLAB_CCACHE ccache)
set(trees_cache "${CMAKE_BINARY_DIR}/trees-ccache")
if(DEFINED ENV{RAYLAB_TREES_CCACHE_DIR})
  set(trees_cache "$ENV{RAYLAB_TREES_CCACHE_DIR}")
endif()
set(RAYLAB_TREES_CCACHE_DIR "${trees_cache}" CACHE PATH
    "The compiler cache of the trees the slow tests build (when ccache is installed)")
set(RAYLAB_TREES_CCACHE_ENVIRONMENT "")
if(NOT RAYLAB_CCACHE)
  return()
endif()
# The paths below the base folder are made relative: the source folder when the build folder is in
# it (the trees are in the build folder), else the build folder (the trees share, this build not).
cmake_path(IS_PREFIX CMAKE_SOURCE_DIR "${CMAKE_BINARY_DIR}" build_in_source)
if(build_in_source)
  set(base "${CMAKE_SOURCE_DIR}")
else()
  set(base "${CMAKE_BINARY_DIR}")
endif()
set(RAYLAB_TREES_CCACHE_ENVIRONMENT "CCACHE_DIR=${RAYLAB_TREES_CCACHE_DIR}" "CCACHE_BASEDIR=${base}" "CCACHE_NOHASHDIR=1")
if(RAYLAB_HAVE_SOLUTIONS AND NOT CMAKE_CXX_COMPILER_LAUNCHER AND base STREQUAL CMAKE_SOURCE_DIR)
  set(CMAKE_CXX_COMPILER_LAUNCHER ${CMAKE_COMMAND} -E env --unset=CCACHE_DISABLE ${RAYLAB_TREES_CCACHE_ENVIRONMENT}
      ${RAYLAB_CCACHE})
endif()
