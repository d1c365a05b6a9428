// `raylab distribute` hands out no solution (issue 21): no file of the students' tree (written just
// before by the CTest fixture "distributed_tree", tests/grading/CMakeLists.txt) holds a window of
// kWindow characters of solutions/ code, comments and white space removed on both sides, so that
// reformatting or recommenting hides nothing. Windows the stubs of labs/ also hold (the given
// signatures, includes and calls) are left out: they are handed out on purpose. Windows are hashed
// into a set, so each file of the tree is read once, in linear time.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstddef>
#include <deque>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace {

namespace fs = std::filesystem;

constexpr std::size_t kWindow = 60;

std::string readFile(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// The end of the literal that starts at `i` with its quote; a literal never spans lines (so an
// apostrophe in prose costs at most the rest of its line).
std::size_t literalEnd(const std::string& text, std::size_t i) {
    const char quote = text[i];
    std::size_t j = i + 1;
    while (j < text.size() && text[j] != quote && text[j] != '\n')
        j += text[j] == '\\' ? 2 : 1;
    return std::min(j + 1, text.size());
}

bool isSpace(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
}

// The text without its // and /* */ comments and without white space (kept inside literals, where
// "//" is not a comment; their spaces go too, as everywhere).
std::string codeOnly(const std::string& text) {
    std::string code;
    code.reserve(text.size());
    std::size_t i = 0;
    while (i < text.size()) {
        if (text.compare(i, 2, "//") == 0) {
            i = std::min(text.find('\n', i), text.size());
        } else if (text.compare(i, 2, "/*") == 0) {
            const std::size_t close = text.find("*/", i + 2);
            i = close == std::string::npos ? text.size() : close + 2;
        } else if (text[i] == '"' || text[i] == '\'') {
            const std::size_t end = literalEnd(text, i);
            for (; i < end; ++i)
                if (!isSpace(text[i])) code += text[i];
        } else {
            if (!isSpace(text[i])) code += text[i];
            ++i;
        }
    }
    return code;
}

using Windows = std::unordered_set<std::string_view>;

// Every window of `code` (which must outlive the set).
void addWindows(Windows& windows, const std::string& code) {
    for (std::size_t k = 0; k + kWindow <= code.size(); ++k)
        windows.insert(std::string_view(code).substr(k, kWindow));
}

std::map<std::string, fs::path> filesUnder(const fs::path& folder) {
    std::map<std::string, fs::path> files; // sorted, for a stable report
    for (const auto& entry : fs::recursive_directory_iterator(folder))
        if (entry.is_regular_file()) files.emplace(entry.path().lexically_relative(folder).generic_string(), entry.path());
    return files;
}

// The windows of solutions/ code that the stubs do not share, and the solution file each comes from.
// The labs of `given` (a students' tree's framework/given/: the labs its course leaves out and the
// framework calls) ship their reference on purpose: their solutions are left out, and their windows
// are handed out as the stubs' are.
class SolutionWindows {
public:
    SolutionWindows(const SolutionWindows&) = delete; // the windows are views of its own texts
    SolutionWindows& operator=(const SolutionWindows&) = delete;
    SolutionWindows(const fs::path& solutions, const fs::path& stubs, const fs::path& given = {}) {
        for (const fs::path& handedOut : {stubs, given}) {
            if (handedOut.empty() || !fs::is_directory(handedOut)) continue;
            for (const auto& [relative, path] : filesUnder(handedOut))
                if (path.extension() == ".cpp" || path.extension() == ".h")
                    addWindows(m_stubs, m_texts.emplace_back(codeOnly(readFile(path))));
        }
        for (const auto& [relative, path] : filesUnder(solutions)) {
            if (path.extension() != ".cpp" && path.extension() != ".h") continue;
            if (!given.empty() && fs::is_directory(given / *fs::path(relative).begin())) continue;
            const std::string& code = m_texts.emplace_back(codeOnly(readFile(path)));
            for (std::size_t k = 0; k + kWindow <= code.size(); ++k) {
                const std::string_view window = std::string_view(code).substr(k, kWindow);
                if (!m_stubs.count(window)) m_from.emplace(window, "solutions/" + relative);
            }
        }
    }
    std::size_t size() const { return m_from.size(); }
    // The solution file whose window this is, or nullptr.
    const std::string* find(std::string_view window) const {
        const auto hit = m_from.find(window);
        return hit == m_from.end() ? nullptr : &hit->second;
    }

private:
    std::deque<std::string> m_texts; // the windows' storage: a deque never moves what it holds
    Windows m_stubs;
    std::unordered_map<std::string_view, std::string> m_from;
};

// "file holds N windows of solutions/<file>, from: <the first one>", one line for each pair that meet.
std::vector<std::string> leaks(const fs::path& tree, const SolutionWindows& solution) {
    std::vector<std::string> found;
    for (const auto& [relative, path] : filesUnder(tree)) {
        const std::string text = readFile(path);
        if (text.find('\0') != std::string::npos) continue; // images and other binary files
        const std::string code = codeOnly(text);
        std::map<std::string, std::pair<int, std::string>> met; // solution file -> windows, the first
        for (std::size_t k = 0; k + kWindow <= code.size(); ++k)
            if (const std::string* from = solution.find(std::string_view(code).substr(k, kWindow))) {
                auto& [count, first] = met[*from];
                if (count++ == 0) first = code.substr(k, kWindow);
            }
        for (const auto& [from, seen] : met)
            found.push_back(relative + " holds " + std::to_string(seen.first) + " windows of " + from + ", from: " +
                            seen.second);
    }
    return found;
}

std::string lines(const std::vector<std::string>& items) {
    std::string text;
    for (const std::string& item : items)
        text += "\n  " + item;
    return text;
}

const fs::path kSource = RAYLAB_SOURCE_DIR;
const fs::path kTree = RAYLAB_DISTRIBUTED_TREE;

} // namespace

TEST_SUITE("distribute") {

    TEST_CASE("code is compared without comments and white space, literals kept") {
        CHECK(codeOnly("x->y /* a, b */ += 1.5e-3f; // c\ns = \"a // b\"; c = '/';\n") ==
              "x->y+=1.5e-3f;s=\"a//b\";c='/';");
    }

    TEST_CASE("a window shared with the stubs is left out; one the stubs lack is found, however reformatted") {
        const fs::path work = fs::temp_directory_path() / "raylab-distribute-windows-test";
        fs::remove_all(work);
        fs::create_directories(work / "solutions/lab9");
        fs::create_directories(work / "labs/lab9");
        fs::create_directories(work / "tree");
        const std::string given = "void PerspectiveCamera::a_given_signature_long_enough_for_a_window(float sx, float sy) const";
        const std::string answer = "return normalize(topLeft + sx * width * u - sy * height * v - position) * secretFactor;";
        std::ofstream(work / "solutions/lab9/answer.cpp") << given << " {\n    " << answer << "\n}\n";
        std::ofstream(work / "labs/lab9/stub.cpp") << given << " {\n    // TODO\n}\n";
        std::ofstream(work / "tree/given.cpp") << given << " { }\n";
        std::ofstream(work / "tree/copied.md") << "```\n/* the answer */ return normalize(topLeft+sx*width*u\n"
                                                  "   - sy*height*v - position)*secretFactor; // here\n```\n";
        const SolutionWindows solution(work / "solutions", work / "labs");
        const std::vector<std::string> found = leaks(work / "tree", solution);
        REQUIRE_MESSAGE(found.size() == 1, lines(found));
        CHECK(found[0].rfind("copied.md holds ", 0) == 0);
        CHECK(found[0].find("solutions/lab9/answer.cpp") != std::string::npos);
        fs::remove_all(work);
    }

    TEST_CASE("the check finds every solution file in solutions/ itself") {
        const SolutionWindows solution(kSource / "solutions", kSource / "labs");
        CHECK(solution.size() > 1000);
        const std::vector<std::string> found = leaks(kSource / "solutions", solution);
        for (const auto& [relative, path] : filesUnder(kSource / "solutions")) {
            if (path.extension() != ".cpp") continue;
            CHECK_MESSAGE(std::any_of(found.begin(), found.end(),
                                      [&](const std::string& f) { return f.rfind(relative + " holds", 0) == 0; }),
                          relative << " not found in" << lines(found));
        }
    }

    TEST_CASE("no file of the distributed tree holds 60 characters of solution code the stubs do not") {
        REQUIRE_MESSAGE(
            fs::exists(kTree / "labs/lab3_sphere/sphere_geometry.cpp"),
            kTree.string() << " holds no students' tree: run this test through ctest, whose fixture writes it");
        const fs::path given = kTree / "framework/given";
        const std::vector<std::string> found = leaks(kTree, SolutionWindows(kSource / "solutions", kSource / "labs", given));
        CHECK_MESSAGE(found.empty(), found.size() << " files of the students' tree hold solution code:" << lines(found));
        for (const auto& entry : fs::directory_iterator(kTree / "labs")) // a lab handed out is never given
            CHECK_MESSAGE(!fs::exists(given / entry.path().filename()), entry.path().filename() << " is handed out and given");
    }

} // TEST_SUITE
