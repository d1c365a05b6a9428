#pragma once
// A test that needs a program the build does not (python3, chromium, mmdebstrap: what `scripts/setup.sh
// --tests` adds) is skipped where the program is missing, never failed: it prints "skipped: needs X
// (the command that installs it here)", which its ctest entry reads (SKIP_REGULAR_EXPRESSION, set from
// RAYLAB_SKIPPED in tests/CMakeLists.txt). Such a test is a doctest suite of its own, so that the
// skip hides no other case.
#include "grader/sandbox/install_command.h"
#include "grader/sandbox/process.h"

#include <doctest/doctest.h>

#include <filesystem>
#include <string>

namespace raylab::test {

// The program's path; empty, having printed the skip line, where it is not installed.
inline std::filesystem::path neededProgram(const std::string& program, const std::string& debian) {
    const std::filesystem::path found = grader::findProgram(program);
    if (found.empty())
        MESSAGE("skipped: needs " << program << " (" << grader::installCommand(debian, debian, program) << ")");
    return found;
}

} // namespace raylab::test
