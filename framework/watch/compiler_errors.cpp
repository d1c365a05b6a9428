#include "watch/compiler_errors.h"

#include <algorithm>
#include <charconv>
#include <optional>
#include <regex>
#include <sstream>

namespace raylab::watch {

namespace fs = std::filesystem;

namespace {

// A file the compiler named relative to its working folder, somewhere in the build (ccache's base_dir
// makes the paths so): the tree's file at that path once its leading "../" are taken off, when there is one.
std::string treeFile(const fs::path& named, const fs::path& sourceDir) {
    fs::path rest;
    bool leading = true;
    for (const fs::path& part : named) {
        if (leading && part == "..") continue;
        leading = false;
        rest /= part;
    }
    std::error_code error;
    return !rest.empty() && fs::is_regular_file(sourceDir / rest, error) ? rest.generic_string() : named.generic_string();
}

// A line or column number; none when it does not fit an int (`#error x:99999999999:1: error: y` is
// echoed by the compiler under its error: that line is the student's text, not an error).
std::optional<int> number(const std::ssub_match& digits) {
    int value = 0;
    const auto [end, error] = std::from_chars(&*digits.first, &*digits.first + digits.length(), value);
    if (error != std::errc() || end != &*digits.first + digits.length()) return std::nullopt;
    return value;
}

} // namespace

std::vector<CompilerError> compilerErrors(const std::string& output, const fs::path& sourceDir) {
    static const std::regex gnu(R"(^(.+?):(\d+):(\d+): (?:fatal )?error: (.*?)\r?$)");
    static const std::regex msvc(R"(^\s*(.+?)\((\d+)(?:,(\d+))?\): (?:fatal )?error (C\d+: .*?)\r?$)");
    const std::string top = fs::path(sourceDir).lexically_normal().generic_string() + "/";
    std::vector<CompilerError> errors;
    std::istringstream lines(output);
    for (std::string line; std::getline(lines, line);) {
        std::smatch m;
        if (!std::regex_match(line, m, gnu) && !std::regex_match(line, m, msvc)) continue;
        const std::optional<int> lineNumber = number(m[2]), column = m[3].matched ? number(m[3]) : 0;
        if (!lineNumber || !column) continue;
        CompilerError e{fs::path(m[1].str()).lexically_normal().generic_string(), *lineNumber, *column, m[4]};
        if (e.file.starts_with(top)) e.file.erase(0, top.size());
        else if (fs::path(e.file).is_relative()) e.file = treeFile(e.file, sourceDir);
        const auto same = [&](const CompilerError& o) {
            return o.file == e.file && o.line == e.line && o.column == e.column && o.message == e.message;
        };
        if (std::none_of(errors.begin(), errors.end(), same)) errors.push_back(std::move(e));
    }
    return errors;
}

} // namespace raylab::watch
