#include "link_check.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <regex>

namespace raylab::test {

int g_linksChecked = 0;

namespace {

namespace fs = std::filesystem;

bool skippedFolder(const fs::path& dir) {
    const std::string name = dir.filename().string();
    if (name == ".git" || name == "out" || name == "_deps" || name == "node_modules" || name.rfind("build", 0) == 0)
        return true;
    std::error_code error;
    return fs::exists(dir / "CMakeCache.txt", error); // a build tree with another name
}

// The line without its code spans (`...`, ``...``).
std::string withoutCodeSpans(const std::string& line) {
    std::string out;
    std::size_t k = 0;
    while (k < line.size()) {
        if (line[k] != '`') {
            out += line[k++];
            continue;
        }
        std::size_t ticks = 0;
        while (k + ticks < line.size() && line[k + ticks] == '`') ++ticks;
        const std::string fence(ticks, '`');
        const std::size_t close = line.find(fence, k + ticks);
        if (close == std::string::npos) { // an unmatched backtick is text
            out += fence;
            k += ticks;
        } else {
            out += ' ';
            k = close + ticks;
        }
    }
    return out;
}

std::string percentDecoded(const std::string& s) {
    std::string out;
    for (std::size_t k = 0; k < s.size(); ++k) {
        if (s[k] == '%' && k + 2 < s.size() && std::isxdigit(static_cast<unsigned char>(s[k + 1])) &&
            std::isxdigit(static_cast<unsigned char>(s[k + 2]))) {
            out += char(std::stoi(s.substr(k + 1, 2), nullptr, 16));
            k += 2;
        } else {
            out += s[k];
        }
    }
    return out;
}

bool isExternal(const std::string& target) {
    static const std::regex scheme("^[A-Za-z][A-Za-z0-9+.-]*:");
    return target.empty() || target[0] == '#' || std::regex_search(target, scheme);
}

} // namespace

std::vector<fs::path> markdownFiles(const fs::path& root) {
    std::vector<fs::path> files;
    for (auto it = fs::recursive_directory_iterator(root); it != fs::recursive_directory_iterator(); ++it) {
        if (it->is_directory() && skippedFolder(it->path())) {
            it.disable_recursion_pending();
            continue;
        }
        if (it->is_regular_file() && it->path().extension() == ".md") files.push_back(fs::relative(it->path(), root));
    }
    std::sort(files.begin(), files.end());
    return files;
}

std::vector<BrokenLink> brokenLinks(const fs::path& root, const fs::path& markdown) {
    // ](target) covers links, images and a link around an image; an optional "title" follows.
    static const std::regex inlineLink(R"(\]\(\s*<?([^)\s>]+)>?(?:\s+"[^"]*")?\s*\))");
    static const std::regex definition(R"(^\s{0,3}\[[^\]]+\]:\s*<?([^\s>]+)>?)");
    static const std::regex html(R"re(\b(?:src|href)\s*=\s*"([^"]+)")re");
    std::vector<BrokenLink> broken;
    std::ifstream in(root / markdown);
    std::string line;
    int number = 0;
    std::string fence; // the fence of the code block we are in, if any
    while (std::getline(in, line)) {
        ++number;
        const std::size_t first = line.find_first_not_of(" \t");
        if (first != std::string::npos && first < 4 && (line.compare(first, 3, "```") == 0 || line.compare(first, 3, "~~~") == 0)) {
            const std::string marker = line.substr(first, 3);
            if (fence.empty()) fence = marker;
            else if (fence == marker) fence.clear();
            continue;
        }
        if (!fence.empty()) continue;
        const std::string text = withoutCodeSpans(line);
        std::vector<std::string> targets;
        for (const std::regex* re : {&inlineLink, &html})
            for (auto m = std::sregex_iterator(text.begin(), text.end(), *re); m != std::sregex_iterator(); ++m)
                targets.push_back((*m)[1]);
        std::smatch m;
        if (std::regex_search(text, m, definition)) targets.push_back(m[1]);
        for (const std::string& target : targets) {
            if (isExternal(target)) continue;
            // A template's link (tests/labs/toy: a configure_file placeholder such as @N@) leads
            // somewhere only in the copy it is configured into, whose own docs test checks it.
            static const std::regex placeholder("@[A-Za-z_]+@");
            if (std::regex_search(target, placeholder)) continue;
            ++g_linksChecked;
            std::string path = target.substr(0, target.find_first_of("#?"));
            path = percentDecoded(path);
            const fs::path resolved = path[0] == '/' ? fs::path(path.substr(1)) : markdown.parent_path() / path;
            std::error_code error;
            if (!fs::exists(root / resolved, error))
                broken.push_back({markdown, number, target, resolved.lexically_normal()});
        }
    }
    return broken;
}

} // namespace raylab::test
