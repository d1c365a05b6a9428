# Finds raylab's libraries. Where one is missing, the error says how to install it on each system.

function(raylab_missing what debian homebrew vcpkg)
  message(FATAL_ERROR "raylab needs ${what}, which was not found. Install it with\n"
                      "  Debian/Ubuntu: sudo apt-get install ${debian}\n"
                      "  macOS:         brew install ${homebrew}\n"
                      "  Windows:       vcpkg install ${vcpkg}   (then configure with the vcpkg toolchain file)\n")
endfunction()

find_package(glm CONFIG QUIET)
if(NOT TARGET glm::glm)
  raylab_missing("GLM (vector maths)" libglm-dev glm glm)
endif()

find_package(tomlplusplus CONFIG QUIET)
if(NOT TARGET tomlplusplus::tomlplusplus)
  raylab_missing("toml++ (scene files)" libtomlplusplus-dev tomlplusplus tomlplusplus)
endif()

# cmark (the report's Markdown to HTML): pkg-config first, since Debian's libcmark-dev ships a CMake
# package that also wants the cmark program; elsewhere its CMake package.
find_package(PkgConfig QUIET)
if(PkgConfig_FOUND)
  pkg_check_modules(CMARK QUIET IMPORTED_TARGET libcmark)
endif()
add_library(raylab_cmark INTERFACE)
if(CMARK_FOUND)
  target_link_libraries(raylab_cmark INTERFACE PkgConfig::CMARK)
else()
  find_package(cmark CONFIG QUIET)
  if(NOT TARGET cmark::cmark)
    raylab_missing("cmark (the report's Markdown)" libcmark-dev cmark cmark)
  endif()
  target_link_libraries(raylab_cmark INTERFACE cmark::cmark)
endif()

find_package(CLI11 CONFIG QUIET)
if(NOT TARGET CLI11::CLI11)
  raylab_missing("CLI11 (command line)" libcli11-dev cli11 cli11)
endif()

# stb_image / stb_image_write: only their headers are taken (Debian's pkg-config stb also offers a
# compiled libstb, not used); framework/src/stb_implementation.cpp compiles them, with zlib as the
# PNG writer's deflate (docs/performance.md).
find_package(PkgConfig QUIET)
if(PkgConfig_FOUND)
  pkg_check_modules(STB QUIET stb)
endif()
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
  find_package(doctest CONFIG QUIET)
  if(NOT TARGET doctest::doctest)
    raylab_missing("doctest (tests; or configure with -DBUILD_TESTING=OFF)" doctest-dev doctest doctest)
  endif()
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
