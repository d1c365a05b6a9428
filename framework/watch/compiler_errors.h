#pragma once
// The errors of a compiler's output, as the watch page shows them: file, line, column and message
// (GCC's and Clang's "file:line:column: error: ...", MSVC's "file(line,column): error C...: ...").

#include <filesystem>
#include <string>
#include <vector>

namespace raylab::watch {

struct CompilerError {
    std::string file; // relative to the source tree when it is in it
    int line = 0, column = 0;
    std::string message;
};

// Each error once, in the output's order; `sourceDir` makes the files relative.
std::vector<CompilerError> compilerErrors(const std::string& output, const std::filesystem::path& sourceDir);

} // namespace raylab::watch
