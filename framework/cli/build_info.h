#pragma once
// What this raylab program was built from; CMake sets these (framework/CMakeLists.txt).

namespace raylab::build {

// Which program this is: program_identity.cpp, compiled for each (the rest of the tool is shared).
extern const char* const kImpl;       // "student" or "reference"
extern const char* const kLabOrigins; // e.g. "lab1=labs lab2=solutions ..."
// The tree and the build this program came from, also in program_identity.cpp: set on that file's
// command line alone, so that the rest of the tool compiles the same in every tree (ccache shares it).
extern const char* const kSourceDir;
extern const char* const kBinaryDir; // where the raylab programs are
extern const char* const kBuildDir;  // the build folder (`cmake --build` it)
extern const char* const kBuildType; // "Release", "Debug"... (CMake's config)
extern const char* const kVersion;   // the project's version (CMakeLists.txt)

} // namespace raylab::build
