// `raylab distribute` hands out no solution: no file of the students' tree (written just before by
// the CTest fixture "distributed_tree", tests/grading/CMakeLists.txt) holds a run of kRun tokens
// equal to a run in the body of a function of solutions/*.cpp. Tokens are C++'s, roughly:
// identifiers, numbers, string and character literals, one punctuation character each; comments and
// white space are not tokens, so reformatting or recommenting a body does not hide it.
#include <doctest/doctest.h>

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

namespace {

namespace fs = std::filesystem;

constexpr std::size_t kRun = 25;

struct Token {
    std::string text;
    int line = 0;
};

std::string readFile(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

bool isWordChar(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}
bool isDigit(char c) {
    return std::isdigit(static_cast<unsigned char>(c)) != 0;
}

// The end of the number that starts at `i`: digits, letters (suffixes, hex), '.', digit separators,
// and the sign of an exponent (1e-9, 0x1p+3).
std::size_t numberEnd(const std::string& text, std::size_t i) {
    std::size_t j = i + 1;
    while (j < text.size()) {
        const char c = text[j];
        const char before = text[j - 1];
        const bool exponentSign =
            (c == '+' || c == '-') && (before == 'e' || before == 'E' || before == 'p' || before == 'P');
        if (!isWordChar(c) && c != '.' && c != '\'' && !exponentSign) break;
        ++j;
    }
    return j;
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

std::vector<Token> tokenize(const std::string& text) {
    std::vector<Token> tokens;
    int line = 1;
    std::size_t i = 0;
    while (i < text.size()) {
        const char c = text[i];
        std::size_t end = i + 1;
        if (text.compare(i, 2, "//") == 0) {
            end = std::min(text.find('\n', i), text.size());
        } else if (text.compare(i, 2, "/*") == 0) {
            const std::size_t close = text.find("*/", i + 2);
            end = close == std::string::npos ? text.size() : close + 2;
        } else if (std::isspace(static_cast<unsigned char>(c))) {
        } else if (isDigit(c) || (c == '.' && i + 1 < text.size() && isDigit(text[i + 1]))) {
            end = numberEnd(text, i);
            tokens.push_back({text.substr(i, end - i), line});
        } else if (isWordChar(c)) {
            while (end < text.size() && isWordChar(text[end]))
                ++end;
            tokens.push_back({text.substr(i, end - i), line});
        } else if (c == '"' || c == '\'') {
            end = literalEnd(text, i);
            tokens.push_back({text.substr(i, end - i), line});
        } else {
            tokens.push_back({std::string(1, c), line});
        }
        for (std::size_t k = i; k < end; ++k)
            line += text[k] == '\n';
        i = end;
    }
    return tokens;
}

struct Function {
    std::string where;             // "solutions/lab3_sphere/sphere_geometry.cpp SphereGeometry::intersect"
    std::vector<std::string> body; // from its '{' to its '}'
};

// "Class::name" of the function whose body opens at `open`: the name before the first '(' of the
// declaration, which starts after the previous ';', '{' or '}'.
std::string functionName(const std::vector<Token>& tokens, std::size_t open) {
    std::size_t start = open;
    while (start > 0 && tokens[start - 1].text != ";" && tokens[start - 1].text != "{" && tokens[start - 1].text != "}")
        --start;
    std::size_t paren = start;
    while (paren < open && tokens[paren].text != "(")
        ++paren;
    if (paren == start || paren == open) return "?";
    std::string name = tokens[paren - 1].text;
    if (paren >= start + 4 && tokens[paren - 2].text == ":" && tokens[paren - 3].text == ":")
        name = tokens[paren - 4].text + "::" + name;
    return name;
}

// The bodies of the functions defined at namespace scope (free functions and members defined out of
// their class, which is how every lab file is written).
std::vector<Function> functionBodies(const fs::path& file, const std::string& label) {
    const std::vector<Token> tokens = tokenize(readFile(file));
    std::vector<Function> functions;
    const std::set<std::string> beforeBody{")", "const", "noexcept", "override"};
    std::vector<bool> namespaceBraces; // one entry an open brace: does it open a namespace?
    for (std::size_t k = 0; k < tokens.size(); ++k) {
        const std::string& t = tokens[k].text;
        if (t == "}" && !namespaceBraces.empty()) namespaceBraces.pop_back();
        if (t != "{") continue;
        const bool opensNamespace =
            (k >= 1 && tokens[k - 1].text == "namespace") || (k >= 2 && tokens[k - 2].text == "namespace");
        bool atNamespaceScope = true;
        for (bool isNamespace : namespaceBraces)
            atNamespaceScope = atNamespaceScope && isNamespace;
        if (opensNamespace || !atNamespaceScope || k == 0 || !beforeBody.count(tokens[k - 1].text)) {
            namespaceBraces.push_back(opensNamespace);
            continue;
        }
        Function f{label + " " + functionName(tokens, k), {}};
        int depth = 0;
        std::size_t end = k;
        for (; end < tokens.size(); ++end) {
            f.body.push_back(tokens[end].text);
            depth += tokens[end].text == "{" ? 1 : tokens[end].text == "}" ? -1 : 0;
            if (depth == 0) break;
        }
        functions.push_back(std::move(f));
        k = end; // the body's closing brace is consumed with it
    }
    return functions;
}

std::vector<Function> solutionFunctions(const fs::path& solutions) {
    std::vector<Function> functions;
    for (const auto& entry : fs::recursive_directory_iterator(solutions)) {
        if (!entry.is_regular_file() || entry.path().extension() != ".cpp") continue;
        const std::string label = "solutions/" + entry.path().lexically_relative(solutions).generic_string();
        for (Function& f : functionBodies(entry.path(), label))
            functions.push_back(std::move(f));
    }
    return functions;
}

std::string joined(const std::vector<std::string>& tokens, std::size_t from) {
    std::string key;
    for (std::size_t k = from; k < from + kRun; ++k)
        (key += tokens[k]) += '\n';
    return key;
}

// Every run of kRun tokens of every body, and the function it comes from.
std::unordered_map<std::string, std::string> runsOf(const std::vector<Function>& functions) {
    std::unordered_map<std::string, std::string> runs;
    for (const Function& f : functions)
        for (std::size_t k = 0; k + kRun <= f.body.size(); ++k)
            runs.emplace(joined(f.body, k), f.where);
    return runs;
}

// "file:line holds 25 tokens of <function>", one line for each file and function that meet.
std::vector<std::string> leaks(const fs::path& tree, const std::unordered_map<std::string, std::string>& runs) {
    std::vector<std::string> found;
    std::map<std::string, fs::path> files; // sorted, for a stable report
    for (const auto& entry : fs::recursive_directory_iterator(tree))
        if (entry.is_regular_file())
            files.emplace(entry.path().lexically_relative(tree).generic_string(), entry.path());
    for (const auto& [relative, path] : files) {
        const std::string text = readFile(path);
        if (text.find('\0') != std::string::npos) continue; // images and other binary files
        const std::vector<Token> tokens = tokenize(text);
        std::vector<std::string> words;
        for (const Token& t : tokens)
            words.push_back(t.text);
        std::set<std::string> reported;
        for (std::size_t k = 0; k + kRun <= words.size(); ++k) {
            const auto hit = runs.find(joined(words, k));
            if (hit == runs.end() || !reported.insert(hit->second).second) continue;
            found.push_back(relative + ":" + std::to_string(tokens[k].line) + " holds " + std::to_string(kRun) +
                            " tokens of " + hit->second);
        }
    }
    return found;
}

std::string lines(const std::vector<std::string>& items) {
    std::string text;
    for (const std::string& item : items)
        text += "\n  " + item;
    return text;
}

const fs::path kSolutions = fs::path(RAYLAB_SOURCE_DIR) / "solutions";
const fs::path kTree = RAYLAB_DISTRIBUTED_TREE;

} // namespace

TEST_SUITE("distribute") {

    TEST_CASE("the tokenizer drops comments and white space, and keeps literals and numbers whole") {
        std::vector<std::string> words;
        for (const Token& t : tokenize("x->y /* a, b */ += 1.5e-3f; // c\ns = \"a b\"; c = '}';"))
            words.push_back(t.text);
        CHECK(words == std::vector<std::string>{"x", "-", ">", "y", "+", "=", "1.5e-3f", ";", "s", "=", "\"a b\"", ";",
                                                "c", "=", "'}'", ";"});
    }

    TEST_CASE("every function of solutions/ is found, with its body") {
        const std::vector<Function> functions = solutionFunctions(kSolutions);
        std::vector<std::string> names;
        for (const Function& f : functions)
            names.push_back(f.where.substr(f.where.rfind(' ') + 1));
        for (const char* name :
             {"ramp", "fillGradient", "PerspectiveCamera::updateViewport", "PerspectiveCamera::generateRay",
              "cosineShade", "RayCastIntegrator::Li", "SphereGeometry::intersect", "SphereGeometry::computeNormal",
              "PerspectiveCamera::PerspectiveCamera", "Renderer::setNbPixelSamples", "Renderer::renderPixel"})
            CHECK_MESSAGE(std::count(names.begin(), names.end(), name) == 1,
                          name << " not found once among" << lines(names));
        for (const Function& f : functions) {
            CAPTURE(f.where);
            CHECK(f.body.front() == "{");
            CHECK(f.body.back() == "}");
        }
    }

    TEST_CASE("the check finds the solutions themselves") {
        const auto runs = runsOf(solutionFunctions(kSolutions));
        CHECK(runs.size() > 100);
        const std::vector<std::string> found = leaks(kSolutions, runs);
        // Each lab file has a body longer than a run.
        for (const auto& entry : fs::recursive_directory_iterator(kSolutions)) {
            if (entry.path().extension() != ".cpp") continue;
            const std::string file = entry.path().lexically_relative(kSolutions).generic_string() + ":";
            CHECK_MESSAGE(
                std::any_of(found.begin(), found.end(), [&](const std::string& f) { return f.rfind(file, 0) == 0; }),
                file << " not found in" << lines(found));
        }
    }

    TEST_CASE("no file of the distributed tree holds a run of 25 tokens of a solution's function body") {
        REQUIRE_MESSAGE(
            fs::exists(kTree / "labs/lab3_sphere/sphere_geometry.cpp"),
            kTree.string() << " holds no students' tree: run this test through ctest, whose fixture writes it");
        const std::vector<std::string> found = leaks(kTree, runsOf(solutionFunctions(kSolutions)));
        CHECK_MESSAGE(found.empty(), found.size()
                                         << " places of the students' tree hold solution code:" << lines(found));
    }

} // TEST_SUITE
