// The message catalogues (framework/messages/en.toml, fr.toml): the same ids and placeholders in
// both languages, French typography, numbers written each language's way, the language chosen from
// the environment.
#include "support/course.h"
#include "support/scene_files.h"
#include "grader/judge/checks/checks.h"
#include "grader/lab_catalog.h"
#include "src/messages.h"
#include "raylab/todo.h"

#include <doctest/doctest.h>
#include <toml++/toml.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

using namespace raylab;

namespace raylab { // the catalogues as compiled in (framework/messages/messages.cpp.in)
extern const char* const kMessagesEn[];
extern const char* const kMessagesFr[];
} // namespace raylab

namespace {

constexpr std::string_view kCheckTitles = "check_title."; // the checks' titles, and French names of functions in words

// The arguments a message reads: {name}, and the number of {name|one|other}.
std::set<std::string> placeholders(const std::string& text) {
    std::set<std::string> names;
    for (std::size_t open = text.find('{'); open != std::string::npos; open = text.find('{', open + 1)) {
        if (text.compare(open, 2, "{{") == 0) { // a brace, not a placeholder
            ++open;
            continue;
        }
        const std::string inside = text.substr(open + 1, text.find('}', open) - open - 1);
        names.insert(inside.substr(0, inside.find('|')));
    }
    return names;
}

// Sets the environment variables the language is read from, restoring them when it goes.
struct Environment {
    explicit Environment(const char* lcAll, const char* lcMessages, const char* lang) {
        set("LC_ALL", lcAll);
        set("LC_MESSAGES", lcMessages);
        set("LANG", lang);
    }
    ~Environment() {
        for (const auto& [name, value] : saved) set(name.c_str(), value ? value->c_str() : nullptr);
    }
    void set(const char* name, const char* value) {
        if (saved.count(name) == 0) {
            const char* old = std::getenv(name);
            saved[name] = old ? std::optional<std::string>(old) : std::nullopt;
        }
        if (value) ::setenv(name, value, 1);
        else ::unsetenv(name);
    }
    std::map<std::string, std::optional<std::string>> saved;
};

// Restores the language chosen before the test.
struct LanguageScope {
    explicit LanguageScope(Language language) : previous(raylab::language()) { setLanguage(language); }
    ~LanguageScope() { setLanguage(previous); }
    Language previous;
};

} // namespace

TEST_SUITE("messages") {
    TEST_CASE("each catalogue is compiled in parts a compiler accepts, cut after a line, that join into its files") {
        const std::pair<const char* const*, const char*> catalogues[] = {{kMessagesEn, "en.toml"},
                                                                          {kMessagesFr, "fr.toml"}};
        for (const auto& [parts, name] : catalogues) {
            std::size_t count = 0;
            for (const char* const* part = parts; *part != nullptr; ++part, ++count) {
                const std::string_view text(*part);
                // cmake/RaylabEmbedText.cmake's limit; MSVC's is 16,380 bytes a literal.
                CHECK_MESSAGE(text.size() <= 12000, name << " part " << count << ": " << text.size() << " bytes");
                CHECK_MESSAGE((!text.empty() && text.back() == '\n'), name << " part " << count << " ends in a line");
            }
            CHECK_MESSAGE(count > 1, name); // both catalogues are over 12,000 bytes
            // The joined text: framework/messages/<language>.toml, then each lab's own messages, each
            // file whole after its marker line (framework/CMakeLists.txt).
            const std::filesystem::path top = std::filesystem::path(RAYLAB_MESSAGES_DIR).parent_path().parent_path();
            const std::string joined = joinedText(parts), marker = "#@raylab-messages ";
            std::vector<std::string> files;
            for (std::size_t at = joined.find(marker); at != std::string::npos;) {
                const std::size_t end = joined.find('\n', at);
                const std::string file = joined.substr(at + marker.size(), end - at - marker.size());
                const std::size_t next = joined.find(marker, end);
                std::ifstream in(top / file, std::ios::binary);
                const std::string whole{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
                CHECK_MESSAGE(!whole.empty(), file);
                CHECK_MESSAGE(joined.substr(end + 1, next == std::string::npos ? next : next - end - 1) == whole + "\n", file);
                files.push_back(file);
                at = next;
            }
            REQUIRE(!files.empty());
            CHECK(joined.rfind(marker, 0) == 0);
            CHECK(files.front() == "framework/messages/" + std::string(name));
            // Then the course's labs' own, in their order.
            std::vector<std::string> expected{files.front()};
            for (const grader::LabDescription& lab : grader::loadLabCatalog(test::kLabsDir).labs)
                if (const std::string file = "framework/grader/labs/" + lab.id + "/messages." + name; std::filesystem::exists(top / file))
                    expected.push_back(file);
            CHECK(files == expected);
        }
    }

    TEST_CASE("every message id has both languages, with the same placeholders") {
        const auto& en = messageCatalogue(Language::En);
        const auto& fr = messageCatalogue(Language::Fr);
        CHECK(en.size() > 100);
        for (const auto& [id, text] : en) {
            const auto twin = fr.find(id);
            if (twin == fr.end()) {
                FAIL_CHECK("no French for " << id);
                continue;
            }
            CHECK_MESSAGE(placeholders(text) == placeholders(twin->second), id);
        }
        for (const auto& [id, text] : fr)
            if (id.rfind(kCheckTitles, 0) != 0) CHECK_MESSAGE(en.count(id) == 1, "no English for " << id);
    }

    TEST_CASE("every function check has a title in English and in French, keyed by its id") {
        const grader::LabCatalog labs = grader::loadLabCatalog(test::kLabsDir);
        std::set<std::string> titles;
        for (const grader::FunctionCheck& check : grader::functionChecks(labs, 1)) {
            CHECK_MESSAGE(messageCatalogue(Language::En).count(std::string(kCheckTitles) + check.id) == 1, check.id);
            CHECK_MESSAGE(messageCatalogue(Language::Fr).count(std::string(kCheckTitles) + check.id) == 1, check.id);
            const LanguageScope english(Language::En);
            CHECK(titleInLanguage(check.id) != check.id);
            CHECK_MESSAGE(titles.insert(titleInLanguage(check.id)).second, "two checks titled " << titleInLanguage(check.id));
        }
        CHECK(titles.size() >= 3);
    }

    TEST_CASE("a lab function named in words has a French title") {
        const grader::LabCatalog labs = grader::loadLabCatalog(test::kLabsDir);
        for (const grader::LabDescription& lab : labs.labs)
            for (const grader::LabFunction& function : lab.functions)
                if (function.name.find(' ') != std::string::npos) // else a C++ name, the same in French
                    CHECK_MESSAGE(messageCatalogue(Language::Fr).count(std::string(kCheckTitles) + function.name) == 1,
                                  function.name);
    }

    TEST_CASE("not-done-yet names the stub's file from the top of the tree, however the compiler was given it") {
        // ccache with a base folder compiles "../../../labs/..." from inside build/.
        for (const char* given : {"labs/lab2_primary_rays/camera.cpp", "../../../labs/lab2_primary_rays/camera.cpp",
                                  "./labs/lab2_primary_rays/camera.cpp"}) {
            const NotDoneYet e("lab 2", "generateRay", given, 12);
            CHECK(e.file() == "labs/lab2_primary_rays/camera.cpp");
            CHECK_MESSAGE(std::string(e.what()).ends_with(" labs/lab2_primary_rays/camera.cpp:12"), e.what());
        }
    }

    TEST_CASE("French typography: a no-break space before : ; ? ! and %, and « » with no-break spaces") {
        const std::string nbsp = "\u00A0", narrow = "\u202F";
        for (const auto& [id, text] : messageCatalogue(Language::Fr)) {
            for (std::size_t k = 0; k < text.size(); ++k) {
                const char c = text[k];
                const bool prose = (c == ':' || c == ';' || c == '?' || c == '!') &&
                                   (k + 1 == text.size() || text[k + 1] == ' ' || text[k + 1] == ')');
                if (!prose && c != '%') continue;
                const bool spaced = (k >= 2 && text.compare(k - 2, 2, nbsp) == 0) ||
                                    (k >= 3 && text.compare(k - 3, 3, narrow) == 0);
                CHECK_MESSAGE(spaced, id << ": \"" << text << "\" at " << k);
            }
            CHECK_MESSAGE(text.find('\'' + std::string("{")) == std::string::npos, id << ": quotes are « »");
            for (std::size_t open = text.find("«"); open != std::string::npos; open = text.find("«", open + 1))
                CHECK_MESSAGE(text.compare(open + 2, 2, nbsp) == 0, id);
        }
    }

    TEST_CASE("numbers: a decimal point in English, a decimal comma in French") {
        {
            const LanguageScope english(Language::En);
            CHECK(formatNumber(0.005) == "0.005");
            CHECK(formatFixed(-1.25, 3, true) == "-1.250");
            CHECK(tr("number.vector", {{"x", "1"}, {"y", "2"}, {"z", "3"}}) == "(1, 2, 3)");
        }
        const LanguageScope french(Language::Fr);
        CHECK(formatNumber(0.005) == "0,005");
        CHECK(formatNumber(12.5) == "12,5");
        CHECK(formatFixed(0.25, 3, true) == "+0,250");
        CHECK(grader::show(glm::dvec3(0.5, 1., -2.)) == "(0,5\u00A0; 1\u00A0; -2)");
        CHECK(tr("report.total", {{"score", formatNumber(7.5)}, {"max", "10"}}) == "total\u00A0: 7,5 / 10");
    }

    TEST_CASE("placeholders are filled; an unknown id or a missing value is a programming error") {
        const LanguageScope english(Language::En);
        CHECK(tr("report.lab", {{"lab", "3"}}) == "lab 3");
        CHECK(tr(Language::Fr, "report.lab", {{"lab", "3"}}) == "TP 3");
        CHECK_THROWS_AS(tr("no.such.message"), std::logic_error);
        CHECK_THROWS_AS(tr("report.lab"), std::logic_error);
    }

    TEST_CASE("{{ and }} write a brace; a placeholder is a name or name|one|other, anything else is named") {
        CHECK(placeholderProblem("{count|figure|figures} in {lab}, {{x, y}} }} {{").empty());
        CHECK(placeholderProblem("no value for {point, normalize(p - c)}") ==
              "{point, normalize(p - c)} is not a placeholder: {name} or {name|one|other} (write {{ for a brace)");
        CHECK(placeholderProblem("{n|one}") != "");
        CHECK(placeholderProblem("{}") != "");
        CHECK(placeholderProblem("open { never closed") == "a { that no } closes (write {{ for a brace)");
    }

    TEST_CASE("every catalogue file, the framework's and each lab's, has well-formed placeholders: a bad one names file:line") {
        // Read from the files themselves (the compiled catalogue has no lines): the framework's, and
        // the grading folder of every lab there is, whatever the course.
        const std::filesystem::path framework = std::filesystem::path(RAYLAB_MESSAGES_DIR).parent_path();
        std::vector<std::filesystem::path> files;
        for (const auto& entry : std::filesystem::directory_iterator(RAYLAB_MESSAGES_DIR))
            if (entry.path().extension() == ".toml") files.push_back(entry.path());
        for (const auto& lab : std::filesystem::directory_iterator(framework / "grader" / "labs"))
            for (const char* name : {"messages.en.toml", "messages.fr.toml"})
                if (std::filesystem::exists(lab.path() / name)) files.push_back(lab.path() / name);
        REQUIRE(files.size() > 2);
        std::size_t messages = 0;
        for (const std::filesystem::path& file : files) {
            const toml::table table = toml::parse_file(file.string());
            std::function<void(const toml::table&, const std::string&)> walk = [&](const toml::table& t,
                                                                                  const std::string& prefix) {
                for (const auto& [key, node] : t) {
                    const std::string id = prefix + std::string(key.str());
                    if (const toml::table* inner = node.as_table()) walk(*inner, id + ".");
                    else if (const auto* text = node.as_string()) {
                        ++messages;
                        const std::string problem = placeholderProblem(text->get());
                        CHECK_MESSAGE(problem.empty(), file.string() << ":" << node.source().begin.line << ": " << id
                                                                     << ": " << problem);
                    }
                }
            };
            walk(table, "");
        }
        CHECK(messages > 200);
    }

    TEST_CASE("a word agrees with its number: 1 in English; 0 and 1 (any number below 2) in French") {
        const auto summary = [](Language l, int count) {
            return tr(l, "figures.summary", {{"count", std::to_string(count)}, {"rendered", std::to_string(count)},
                                             {"todo", "0"}, {"failed", "0"}});
        };
        CHECK(summary(Language::En, 1).rfind("1 figure: 1 rendered", 0) == 0);
        CHECK(summary(Language::En, 0).rfind("0 figures: 0 rendered", 0) == 0);
        CHECK(summary(Language::En, 10).rfind("10 figures: 10 rendered", 0) == 0);
        CHECK(summary(Language::Fr, 0).rfind("0 figure\u00A0: 0 rendue,", 0) == 0);
        CHECK(summary(Language::Fr, 1).rfind("1 figure\u00A0: 1 rendue,", 0) == 0);
        CHECK(summary(Language::Fr, 2).rfind("2 figures\u00A0: 2 rendues,", 0) == 0);
        const auto pass = [](Language l, int outliers) {
            return tr(l, "compare.statistical_pass", {{"bias", "0"}, {"outliers", std::to_string(outliers)}, {"rmse", "1"}});
        };
        CHECK(pass(Language::Fr, 0).find(", 0 pixel aberrant, ") != std::string::npos);
        CHECK(pass(Language::Fr, 3).find(", 3 pixels aberrants, ") != std::string::npos);
        CHECK(pass(Language::En, 1).find(", 1 outlier, ") != std::string::npos);
        CHECK(pass(Language::En, 0).find(", 0 outliers, ") != std::string::npos);
        // Decimals, in each language's way of writing them.
        CHECK(tr(Language::Fr, "report.lab_points", {{"lab", "1"}, {"points", "0,5"}, {"max", "1,5"}}) == "TP 1\u00A0: 0,5 / 1,5 point");
        CHECK(tr(Language::En, "report.lab_points", {{"lab", "1"}, {"points", "0.5"}, {"max", "1.5"}}) == "lab 1: 0.5 / 1.5 points");
        CHECK_THROWS_AS(tr(Language::En, "figures.summary", {{"count", "many"}, {"rendered", "1"}, {"todo", "0"}, {"failed", "0"}}),
                        std::logic_error);
    }

    TEST_CASE("a check's failures that share a hint are one line, with how many more there are") {
        const LanguageScope english(Language::En);
        grader::Judge judge;
        for (int k = 0; k < 14; ++k) judge.fail("u of camera " + std::to_string(k), "a", "b", "u = cross(up, w)");
        judge.fail("v", "c", "d", "v = cross(w, u)");
        judge.fail("w", "e", "f", "u = cross(up, w)");
        CHECK(judge.message() == "u of camera 0: expected a, got b. Hint: u = cross(up, w) (and 14 more cases with the same hint)\n"
                                 "v: expected c, got d. Hint: v = cross(w, u)");
    }

    TEST_CASE("the language comes from LC_ALL, then LC_MESSAGES, then LANG: fr_* gives French") {
        {
            const Environment e(nullptr, nullptr, "fr_FR.UTF-8");
            CHECK(languageFromEnvironment() == Language::Fr);
        }
        {
            const Environment e(nullptr, nullptr, "en_GB.UTF-8");
            CHECK(languageFromEnvironment() == Language::En);
        }
        {
            const Environment e("C", nullptr, "fr_FR.UTF-8");
            CHECK(languageFromEnvironment() == Language::En);
        }
        {
            const Environment e("", "fr_CA.UTF-8", "en_US.UTF-8");
            CHECK(languageFromEnvironment() == Language::Fr);
        }
        {
            const Environment e(nullptr, nullptr, nullptr);
            CHECK(languageFromEnvironment() == Language::En);
        }
        CHECK(parseLanguage("fr") == Language::Fr);
        CHECK(parseLanguage("en") == Language::En);
        CHECK_FALSE(parseLanguage("de"));
    }
}

TEST_SUITE("messages: lab 4") {
    TEST_CASE("not-done-yet says lab 4's lookAt constructor, a function named in words, in French") {
        if (!test::labInCourse(test::kLabsDir, 4)) return;
        const LanguageScope french(Language::Fr);
        const std::string said =
            NotDoneYet("lab 4", "the lookAt constructor PerspectiveCamera(width, height, position, target, up, fovy)",
                       "look_at.cpp", 18)
                .what();
        CHECK_MESSAGE(said.find("écrivez le constructeur lookAt PerspectiveCamera(") != std::string::npos, said);
        CHECK_MESSAGE(said.find("the lookAt") == std::string::npos, said);
    }
}
