#pragma once
// Where a line of code is: the file and line of the call whose default argument is here(), as
// std::source_location would give (Clang 14 lacks it with libstdc++; GCC, Clang and MSVC have these
// builtins). The registries keep it so that an error can name the line that registered something.

#include <string>

namespace raylab {

struct SourcePlace {
    const char* file = "";
    unsigned line = 0;
    static constexpr SourcePlace here(const char* file = __builtin_FILE(), unsigned line = __builtin_LINE()) {
        return {file, line};
    }
    // "framework/grader/labs/<lab>/checks.cpp:75": from the tree's top when the path has one.
    std::string shown() const {
        const std::string path = file;
        const std::size_t top = path.rfind("framework/");
        return (top != std::string::npos ? path.substr(top) : path) + ":" + std::to_string(line);
    }
};

} // namespace raylab
