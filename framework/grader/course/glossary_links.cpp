#include "grader/course/glossary_links.h"

#include "src/messages.h"

#include <cctype>
#include <set>
#include <sstream>

namespace raylab::grader {

namespace {

bool isWordChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Whether `line` holds `term` as a word of its own (LSB, not LSBs or a file name's part).
bool holdsWord(const std::string& line, const std::string& term) {
    for (std::size_t at = line.find(term); at != std::string::npos; at = line.find(term, at + 1)) {
        const bool startsWord = at == 0 || !isWordChar(line[at - 1]);
        const std::size_t end = at + term.size();
        if (startsWord && (end == line.size() || !isWordChar(line[end]))) return true;
    }
    return false;
}

} // namespace

const std::vector<std::pair<std::string, std::string>>& glossaryTerms() {
    static const std::vector<std::pair<std::string, std::string>> terms{
        {"LSB", "lsb"}, {"RMSE", "rmse"}, {"NaN", "nan"}};
    return terms;
}

std::string withGlossaryLinks(const std::string& text) {
    std::set<std::string> linked;
    std::istringstream lines(text);
    std::string out;
    for (std::string line; std::getline(lines, line);) {
        std::string links;
        for (const auto& [term, anchor] : glossaryTerms())
            if (linked.count(term) == 0 && holdsWord(line, term)) {
                linked.insert(term);
                links += (links.empty() ? "" : ", ") + tr("glossary.file") + "#" + anchor;
            }
        out += line;
        if (!links.empty()) out += " (" + tr("glossary.see", {{"links", links}}) + ")";
        out += "\n";
    }
    if (!text.empty() && text.back() != '\n' && !out.empty()) out.pop_back();
    return out;
}

} // namespace raylab::grader
