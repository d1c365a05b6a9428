#pragma once
// What this raylab program was built from; CMake sets these (framework/CMakeLists.txt).

#include <sstream>
#include <string>

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

// Where this program took lab `number` from, read off kLabOrigins: "labs", "solutions", "stubs"
// (framework/stubs/: the lab as handed out, standing for a lab whose code does not compile); ""
// when the program has no such lab.
inline std::string labOrigin(int number) {
    const std::string key = "lab" + std::to_string(number) + "=";
    std::istringstream origins(kLabOrigins);
    for (std::string origin; origins >> origin;)
        if (origin.starts_with(key)) return origin.substr(key.size());
    return "";
}

} // namespace raylab::build
