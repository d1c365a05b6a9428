# Finds raylab's libraries. Where one is missing, the error says how to install it on each system.

function(raylab_missing what debian homebrew vcpkg)
  message(FATAL_ERROR "raylab needs ${what}, which was not found. Install it with\n"
                      "  Debian/Ubuntu: sudo apt-get install ${debian}\n"
                      "  macOS:         brew install ${homebrew}\n"
                      "  Windows:       vcpkg install ${vcpkg}   (then configure with the vcpkg toolchain file)\n")
endfunction()

# raylab_require_package(PACKAGE TARGET WHAT DEBIAN HOMEBREW VCPKG): PACKAGE's CMake package, unless
# TARGET is already there; stops with raylab_missing's advice when TARGET is still missing.
macro(raylab_require_package package target what debian homebrew vcpkg)
  if(NOT TARGET ${target})
    find_package(${package} CONFIG QUIET)
  endif()
  if(NOT TARGET ${target})
    raylab_missing("${what}" ${debian} ${homebrew} ${vcpkg})
  endif()
endmacro()

# raylab_pkg_check(PREFIX ARGS...): pkg_check_modules(PREFIX QUIET ARGS...) where pkg-config is
# installed; elsewhere PREFIX_FOUND stays unset.
macro(raylab_pkg_check prefix)
  find_package(PkgConfig QUIET)
  if(PkgConfig_FOUND)
    pkg_check_modules(${prefix} QUIET ${ARGN})
  endif()
endmacro()

raylab_require_package(glm glm::glm "GLM (vector maths)" libglm-dev glm glm)
raylab_require_package(tomlplusplus tomlplusplus::tomlplusplus "toml++ (scene files)" libtomlplusplus-dev tomlplusplus
                       tomlplusplus)

# cmark (the report's Markdown to HTML): pkg-config first, since Debian's libcmark-dev ships a CMake
# package that also wants the cmark program; elsewhere its CMake package.
raylab_pkg_check(CMARK IMPORTED_TARGET libcmark)
add_library(raylab_cmark INTERFACE)
if(CMARK_FOUND)
  target_link_libraries(raylab_cmark INTERFACE PkgConfig::CMARK)
else()
  raylab_require_package(cmark cmark::cmark "cmark (the report's Markdown)" libcmark-dev cmark cmark)
  target_link_libraries(raylab_cmark INTERFACE cmark::cmark)
endif()

raylab_require_package(CLI11 CLI11::CLI11 "CLI11 (command line)" libcli11-dev cli11 cli11)

# stb_image / stb_image_write: only their headers are taken (Debian's pkg-config stb also offers a
# compiled libstb, not used); framework/src/stb_implementation.cpp compiles them, with zlib as the
# PNG writer's deflate (docs/performance.md).
raylab_pkg_check(STB stb)
find_path(STB_INCLUDE_DIR stb_image_write.h HINTS ${STB_INCLUDE_DIRS} PATH_SUFFIXES stb)
if(NOT STB_INCLUDE_DIR)
  raylab_missing("stb (image files)" libstb-dev "stb" stb)
endif()
find_package(ZLIB QUIET)
if(NOT TARGET ZLIB::ZLIB)
  raylab_missing("zlib (PNG compression)" zlib1g-dev zlib zlib)
endif()
add_library(raylab_stb STATIC ${CMAKE_SOURCE_DIR}/framework/src/stb_implementation.cpp)
target_include_directories(raylab_stb SYSTEM PUBLIC ${STB_INCLUDE_DIR})
target_link_libraries(raylab_stb PRIVATE ZLIB::ZLIB)

if(BUILD_TESTING)
  raylab_require_package(doctest doctest::doctest "doctest (tests; or configure with -DBUILD_TESTING=OFF)" doctest-dev
                         doctest doctest)
endif()

# Our own code compiles without warnings at these levels.
add_library(raylab_warnings INTERFACE)
if(MSVC)
  target_compile_options(raylab_warnings INTERFACE /W4 /permissive-)
else()
  target_compile_options(raylab_warnings INTERFACE -Wall -Wextra -Wpedantic)
  # __FILE__ relative to the source tree: "lab 2 not done yet: write ... in labs/lab2_.../file.cpp:12".
  target_compile_options(raylab_warnings INTERFACE -fmacro-prefix-map=${CMAKE_SOURCE_DIR}/=)
endif()
