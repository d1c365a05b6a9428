#pragma once
// What this raylab program was built from; CMake sets these (framework/CMakeLists.txt).

namespace raylab::build {

// Which program this is: program_identity.cpp, compiled for each (the rest of the tool is shared).
extern const char* const kImpl;       // "student" or "reference"
extern const char* const kLabOrigins; // e.g. "lab1=labs lab2=solutions ..."
inline constexpr const char* kScenesDir = RAYLAB_SCENES_DIR;    // the scenes/ folder of the source tree
inline constexpr const char* kSourceDir = RAYLAB_SOURCE_DIR;
inline constexpr const char* kBinaryDir = RAYLAB_BINARY_DIR;    // where the raylab programs are
inline constexpr const char* kBuildDir = RAYLAB_BUILD_DIR;      // the build folder (`cmake --build` it)
inline constexpr const char* kBuildType = RAYLAB_BUILD_TYPE;    // "Release", "Debug"... (CMake's config)
inline constexpr const char* kVersion = RAYLAB_VERSION;        // the project's version (CMakeLists.txt)

} // namespace raylab::build
