# Cross-compiling raylab for 64-bit Windows with Debian's MinGW-w64 (`apt-get install
# g++-mingw-w64-x86-64-posix libz-mingw-w64-dev`): the students' tree, run under Wine by
# scripts/windows_check.sh. The POSIX-threads variant of the compiler: std::thread needs it.
#   cmake -S . -B build-mingw --toolchain cmake/toolchains/mingw-w64.cmake -DBUILD_TESTING=OFF
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR x86_64)
set(CMAKE_C_COMPILER x86_64-w64-mingw32-gcc-posix)
set(CMAKE_CXX_COMPILER x86_64-w64-mingw32-g++-posix)
set(CMAKE_RC_COMPILER x86_64-w64-mingw32-windres)

# Libraries and headers from MinGW's own prefix only: Linux's /usr/include would shadow its C library.
set(CMAKE_FIND_ROOT_PATH /usr/x86_64-w64-mingw32)
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)

# Each program one .exe that runs without MinGW's DLLs beside it (libstdc++, winpthread, zlib).
set(CMAKE_EXE_LINKER_FLAGS_INIT -static)
set(ZLIB_USE_STATIC_LIBS ON)

# The header-only libraries (GLM, toml++, CLI11, nlohmann-json, stb) are the build machine's, each
# seen through a folder of its own (RAYLAB_THIRD_PARTY_DIR/<name>/include, as third_party/ would hold
# them): /usr/include itself on the include path would bring Linux's C headers in.
set(raylab_host_headers "glm:glm" "tomlplusplus:toml++" "cli11:CLI" "nlohmann_json:nlohmann")
set(RAYLAB_THIRD_PARTY_DIR ${CMAKE_BINARY_DIR}/host-headers)
foreach(entry IN LISTS raylab_host_headers)
  string(REPLACE ":" ";" entry ${entry})
  list(GET entry 0 name)
  list(GET entry 1 folder)
  if(EXISTS /usr/include/${folder} AND NOT EXISTS ${RAYLAB_THIRD_PARTY_DIR}/${name}/include/${folder})
    file(MAKE_DIRECTORY ${RAYLAB_THIRD_PARTY_DIR}/${name}/include)
    file(CREATE_LINK /usr/include/${folder} ${RAYLAB_THIRD_PARTY_DIR}/${name}/include/${folder} SYMBOLIC)
  endif()
endforeach()
if(EXISTS /usr/include/stb/stb_image_write.h AND NOT EXISTS ${RAYLAB_THIRD_PARTY_DIR}/stb/include)
  file(MAKE_DIRECTORY ${RAYLAB_THIRD_PARTY_DIR}/stb)
  file(CREATE_LINK /usr/include/stb ${RAYLAB_THIRD_PARTY_DIR}/stb/include SYMBOLIC)
endif()

# pkg-config sees MinGW's packages only (not the build machine's libseccomp or cmark).
set(ENV{PKG_CONFIG_LIBDIR} /usr/x86_64-w64-mingw32/lib/pkgconfig)
set(ENV{PKG_CONFIG_PATH} "")
# Debian has no MinGW package of cmark, libzip or cpp-httplib: raylab report, raylab watch and raylab
# autograder gradescope (an instructor's command) are left out; the tests too (-DBUILD_TESTING=OFF),
# which need the first two.
set(RAYLAB_REPORT OFF CACHE BOOL "Build raylab report, the lab report kit (needs cmark)")
set(RAYLAB_GRADESCOPE_ZIP OFF CACHE BOOL "Build raylab autograder gradescope (needs libzip)")
set(RAYLAB_WATCH OFF CACHE BOOL "Build raylab watch, the live page (needs cpp-httplib)")
set(BUILD_TESTING OFF CACHE BOOL "Build the tests")
