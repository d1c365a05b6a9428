# Finds raylab's libraries. Where one is missing, the error says how to install it on this machine.
#
# Grading needs only a C++20 compiler, CMake and zlib: the header-only libraries (GLM, stb, toml++,
# CLI11, nlohmann-json) come from the system when it has them, else from third_party/<name>/include,
# which `raylab autograder` fills from the instructor's headers (Gradescope's Ubuntu 22.04 has no
# toml++). The compiled libraries of the tools and tests (cmark, libzip, doctest, yaml-cpp) are not
# looked for when RAYLAB_GRADING_ONLY is ON.

# The command is this machine's (cmake/RaylabInstallCommand.cmake); scripts/setup.sh installs them all.
function(raylab_missing what debian homebrew vcpkg)
  raylab_install_command(command "${debian}" "${homebrew}" "${vcpkg}")
  message(FATAL_ERROR "raylab needs ${what}, which was not found. Install it with\n  ${command}\n")
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

# Where the header-only libraries are looked for when the system has no CMake package of them:
# third_party/<name>/include, or another folder of the same shape (the MinGW toolchain's view of the
# build machine's headers, cmake/toolchains/mingw-w64.cmake).
if(NOT RAYLAB_THIRD_PARTY_DIR)
  set(RAYLAB_THIRD_PARTY_DIR ${CMAKE_SOURCE_DIR}/third_party)
  set(raylab_third_party_shown third_party) # as the configure log says it (the autograder's test reads it)
else()
  set(raylab_third_party_shown ${RAYLAB_THIRD_PARTY_DIR})
endif()

# Where each header-only library was found, for `raylab autograder` to copy into third_party/: lines
# of framework/cli/third_party_sources.h (generated below).
set(RAYLAB_THIRD_PARTY_ENTRIES "")

# raylab_record_headers(NAME INCLUDE_DIR DEBIAN ENTRIES...): NAME's headers are ENTRIES (files or
# folders) of INCLUDE_DIR; its licence is the file its package installed beside them (Debian's
# copyright, vcpkg's share/<name>/copyright, or a LICENSE at the prefix), empty when none is found.
function(raylab_record_headers name include_dir debian)
  set(licence_var RAYLAB_LICENCE_${name})
  find_file(${licence_var} NAMES copyright LICENSE LICENSE.txt LICENSE.md COPYING LICENCE
            PATHS ${include_dir}/../share/doc/${debian} ${include_dir}/../../share/doc/${debian}
                  ${include_dir}/../share/${name} ${include_dir}/../share/licenses/${name} ${include_dir}/..
            NO_DEFAULT_PATH)
  set(licence ${${licence_var}})
  if(NOT licence)
    set(licence "")
  endif()
  list(JOIN ARGN ";" entries)
  set(RAYLAB_THIRD_PARTY_ENTRIES
      "${RAYLAB_THIRD_PARTY_ENTRIES}    {\"${name}\", R\"raylab(${include_dir})raylab\", \"${entries}\", R\"raylab(${licence})raylab\"},\n"
      PARENT_SCOPE)
endfunction()

# raylab_header_library(NAME PACKAGE TARGET HEADER WHAT DEBIAN HOMEBREW VCPKG ENTRIES...): TARGET from the
# system's CMake package PACKAGE when there, else an interface target over third_party/NAME/include;
# HEADER is one of its headers, relative to the include folder.
function(raylab_header_library name package target header what debian homebrew vcpkg)
  if(NOT TARGET ${target})
    find_package(${package} CONFIG QUIET)
  endif()
  set(bundled ${RAYLAB_THIRD_PARTY_DIR}/${name}/include)
  if(TARGET ${target})
    get_target_property(hints ${target} INTERFACE_INCLUDE_DIRECTORIES)
    find_path(RAYLAB_HEADERS_${name} ${header} HINTS ${hints} NO_CACHE)
    set(include_dir ${RAYLAB_HEADERS_${name}})
  elseif(EXISTS ${bundled}/${header})
    add_library(${target} INTERFACE IMPORTED GLOBAL)
    set_target_properties(${target} PROPERTIES INTERFACE_INCLUDE_DIRECTORIES ${bundled})
    set(include_dir ${bundled})
    message(STATUS "raylab: ${what} from ${raylab_third_party_shown}/${name}")
  else()
    raylab_missing("${what}" ${debian} ${homebrew} ${vcpkg})
  endif()
  raylab_record_headers(${name} "${include_dir}" ${debian} ${ARGN})
  set(RAYLAB_THIRD_PARTY_ENTRIES "${RAYLAB_THIRD_PARTY_ENTRIES}" PARENT_SCOPE)
endfunction()

raylab_header_library(glm glm glm::glm glm/glm.hpp "GLM (vector maths)" libglm-dev glm glm glm)
# Debian's toml++ is a compiled library; the bundled headers are used header-only (toml++'s default).
raylab_header_library(tomlplusplus tomlplusplus tomlplusplus::tomlplusplus toml++/toml.h "toml++ (scene files)"
                      libtomlplusplus-dev tomlplusplus tomlplusplus toml++)
raylab_header_library(cli11 CLI11 CLI11::CLI11 CLI/CLI.hpp "CLI11 (command line)" libcli11-dev cli11 cli11 CLI)
raylab_header_library(nlohmann_json nlohmann_json nlohmann_json::nlohmann_json nlohmann/json.hpp
                      "nlohmann-json (grader reports)" nlohmann-json3-dev nlohmann-json nlohmann-json nlohmann)

# stb_image / stb_image_write: only their headers are taken (Debian's pkg-config stb also offers a
# compiled libstb, not used); framework/src/stb_implementation.cpp compiles them, with zlib as the
# PNG writer's deflate (docs/performance.md).
raylab_pkg_check(STB stb)
find_path(STB_INCLUDE_DIR stb_image_write.h HINTS ${STB_INCLUDE_DIRS} PATH_SUFFIXES stb)
if(NOT STB_INCLUDE_DIR AND EXISTS ${RAYLAB_THIRD_PARTY_DIR}/stb/include/stb_image_write.h)
  set(STB_INCLUDE_DIR ${RAYLAB_THIRD_PARTY_DIR}/stb/include CACHE PATH "stb's headers" FORCE)
  message(STATUS "raylab: stb (image files) from ${raylab_third_party_shown}/stb")
endif()
if(NOT STB_INCLUDE_DIR)
  raylab_missing("stb (image files)" libstb-dev "stb" stb)
endif()
raylab_record_headers(stb "${STB_INCLUDE_DIR}" libstb-dev stb_image.h stb_image_write.h)
find_package(ZLIB QUIET)
if(NOT TARGET ZLIB::ZLIB)
  raylab_missing("zlib (PNG compression)" zlib1g-dev zlib zlib)
endif()
add_library(raylab_stb STATIC ${CMAKE_SOURCE_DIR}/framework/src/stb_implementation.cpp)
target_include_directories(raylab_stb SYSTEM PUBLIC ${STB_INCLUDE_DIR})
target_link_libraries(raylab_stb PRIVATE ZLIB::ZLIB)

configure_file(${CMAKE_CURRENT_LIST_DIR}/third_party_sources.h.in ${CMAKE_BINARY_DIR}/generated/third_party_sources.h
               @ONLY)

# The compiled libraries of the tools, each for one command that a build may go without (where the
# library has no package, as with MinGW on Debian: cmake/toolchains/mingw-w64.cmake).
option(RAYLAB_REPORT "Build raylab report, the lab report kit (needs cmark)" ON)
option(RAYLAB_GRADESCOPE_ZIP "Build raylab autograder gradescope (needs libzip)" ON)
option(RAYLAB_WATCH "Build raylab watch, the live page (needs cpp-httplib)" ON)
if(BUILD_TESTING AND NOT (RAYLAB_REPORT AND RAYLAB_GRADESCOPE_ZIP))
  message(FATAL_ERROR "The tests need raylab report and raylab autograder gradescope: configure with "
                      "-DBUILD_TESTING=OFF, or with RAYLAB_REPORT and RAYLAB_GRADESCOPE_ZIP ON")
endif()

if(NOT RAYLAB_GRADING_ONLY AND RAYLAB_REPORT)
  # cmark (the report's Markdown to HTML): pkg-config first, since Debian's libcmark-dev ships a CMake
  # package that also wants the cmark program; elsewhere its CMake package.
  raylab_pkg_check(CMARK IMPORTED_TARGET libcmark)
  add_library(raylab_cmark INTERFACE)
  if(CMARK_FOUND)
    target_link_libraries(raylab_cmark INTERFACE PkgConfig::CMARK)
  else()
    find_package(cmark CONFIG QUIET)
    if(TARGET cmark::cmark_static AND NOT TARGET cmark::cmark) # vcpkg's static cmark (x64-windows-static)
      target_link_libraries(raylab_cmark INTERFACE cmark::cmark_static)
    else()
      raylab_require_package(cmark cmark::cmark "cmark (the report's Markdown)" libcmark-dev cmark cmark)
      target_link_libraries(raylab_cmark INTERFACE cmark::cmark)
    endif()
  endif()
endif()

if(NOT RAYLAB_GRADING_ONLY AND RAYLAB_GRADESCOPE_ZIP)
  # libzip: `raylab autograder gradescope` writes Gradescope's zip with it. Found by pkg-config:
  # Debian's CMake package for it names programs (zipcmp ...) that libzip-dev does not install.
  raylab_pkg_check(LIBZIP IMPORTED_TARGET GLOBAL libzip)
  if(TARGET PkgConfig::LIBZIP)
    add_library(libzip::zip ALIAS PkgConfig::LIBZIP)
  else()
    # Homebrew, vcpkg
    raylab_require_package(libzip libzip::zip "libzip (the Gradescope autograder's zip)" libzip-dev libzip libzip)
  endif()
endif()

if(NOT RAYLAB_GRADING_ONLY AND RAYLAB_WATCH)
  # cpp-httplib: `raylab watch`'s server. Its CMake package (vcpkg, Homebrew, Debian 13), else pkg-config
  # (Debian 12's libcpp-httplib-dev, a compiled library with no CMake package).
  find_package(httplib CONFIG QUIET)
  if(NOT TARGET httplib::httplib)
    raylab_pkg_check(HTTPLIB IMPORTED_TARGET GLOBAL cpp-httplib)
    if(TARGET PkgConfig::HTTPLIB)
      add_library(httplib::httplib ALIAS PkgConfig::HTTPLIB)
    endif()
  endif()
  if(NOT TARGET httplib::httplib)
    raylab_missing("cpp-httplib (raylab watch's page; or configure with -DRAYLAB_WATCH=OFF)" libcpp-httplib-dev cpp-httplib
                   cpp-httplib)
  endif()
endif()

if(BUILD_TESTING)
  raylab_require_package(doctest doctest::doctest "doctest (tests; or configure with -DBUILD_TESTING=OFF)" doctest-dev
                         doctest doctest)
endif()

# Our own code compiles without warnings at these levels.
add_library(raylab_warnings INTERFACE)
if(MSVC)
  target_compile_options(raylab_warnings INTERFACE /W4 /permissive-)
  # getenv, fopen, localtime: the standard functions, which MSVC's /W4 calls unsafe (C4996).
  target_compile_definitions(raylab_warnings INTERFACE _CRT_SECURE_NO_WARNINGS)
  # All sources and messages are UTF-8 (the French catalogue, the labs' comments): every target's.
  add_compile_options(/utf-8)
else()
  target_compile_options(raylab_warnings INTERFACE -Wall -Wextra -Wpedantic)
  # __FILE__ relative to the source tree: "lab 2 not done yet: write ... in labs/lab2_.../file.cpp:12".
  target_compile_options(raylab_warnings INTERFACE -fmacro-prefix-map=${CMAKE_SOURCE_DIR}/=)
endif()
