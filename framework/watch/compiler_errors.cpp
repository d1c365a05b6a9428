#include "watch/compiler_errors.h"

#include <algorithm>
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
        CompilerError e{fs::path(m[1].str()).lexically_normal().generic_string(), std::stoi(m[2]),
                        m[3].matched ? std::stoi(m[3]) : 0, m[4]};
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
