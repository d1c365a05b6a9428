#include "watch/compiler_errors.h"

#include <algorithm>
#include <regex>
#include <sstream>

namespace raylab::watch {

namespace fs = std::filesystem;

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
        const auto same = [&](const CompilerError& o) {
            return o.file == e.file && o.line == e.line && o.column == e.column && o.message == e.message;
        };
        if (std::none_of(errors.begin(), errors.end(), same)) errors.push_back(std::move(e));
    }
    return errors;
}

} // namespace raylab::watch
