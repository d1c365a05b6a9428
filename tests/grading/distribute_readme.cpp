// The students' tree's own README.md and LISEZMOI.md (`raylab distribute`): nothing about the
// solutions or out/reference/, every lab's handout, and every command they show exists: each fenced
// command is run with --help (raylab's), found as a workflow preset of the tree (cmake's), or is an
// executable file of the tree (scripts/setup.sh) given options of its own. The build command is the
// one distribute prints.
#include "grader/lab_catalog.h"
#include "support/files.h"
#include "support/run_program.h"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using raylab::test::readFile;

// The words of a shell line before its comment, split on blanks.
std::vector<std::string> argumentsOf(const std::string& command) {
    std::istringstream in(command.substr(0, command.find('#')));
    std::vector<std::string> args;
    for (std::string arg; in >> arg;) args.push_back(arg);
    return args;
}

// The commands of the fenced code blocks of `markdown`, one per line, `a && b` as two.
std::vector<std::vector<std::string>> fencedCommands(const std::string& markdown) {
    std::vector<std::vector<std::string>> commands;
    std::istringstream lines(markdown);
    bool fenced = false;
    for (std::string line; std::getline(lines, line);) {
        if (line.rfind("```", 0) == 0) fenced = !fenced;
        else if (fenced)
            for (std::size_t from = 0; from <= line.size();) {
                const std::size_t to = std::min(line.find("&&", from), line.size());
                if (auto args = argumentsOf(line.substr(from, to - from)); !args.empty()) commands.push_back(args);
                from = to + 2;
            }
    }
    return commands;
}

std::vector<std::string> workflowPresets(const fs::path& tree) {
    const nlohmann::json presets = nlohmann::json::parse(readFile(tree / "CMakePresets.json"));
    std::vector<std::string> names;
    for (const auto& preset : presets.at("workflowPresets"))
        names.push_back(preset.at("name").get<std::string>());
    return names;
}

// The command exists in `tree`: raylab's answers its --help, cmake's preset is one of the tree's.
void checkCommand(const fs::path& tree, const std::vector<std::string>& command, const std::string& readme) {
    const std::string shown = [&] {
        std::string text;
        for (const std::string& a : command) text += a + " ";
        return text;
    }();
    INFO(readme << ": " << shown);
    if (command[0] == "build/bin/raylab") {
        std::vector<std::string> help{RAYLAB_PROGRAM};
        help.insert(help.end(), command.begin() + 1, command.end());
        help.push_back("--help");
        const auto run = raylab::test::runProgram(help, raylab::test::scratchPath("raylab-readme-help.txt"));
        CHECK_MESSAGE(run.status == 0, run.output);
    } else if (command[0] == "cmake") {
        REQUIRE(command.size() == 4);
        CHECK(command[1] == "--workflow");
        CHECK(command[2] == "--preset");
        const std::vector<std::string> presets = workflowPresets(tree);
        CHECK_MESSAGE(std::find(presets.begin(), presets.end(), command[3]) != presets.end(), presets.size() << " workflow presets");
    } else {
        const fs::path script = tree / command[0];
        REQUIRE(fs::is_regular_file(script));
        CHECK((fs::status(script).permissions() & fs::perms::owner_exec) != fs::perms::none);
        // its options (setup.sh --tests) are the script's own
        for (auto option = command.begin() + 1; option != command.end(); ++option) {
            CHECK_MESSAGE(option->starts_with("--"), *option);
            CHECK_MESSAGE(readFile(script).find(*option + ")") != std::string::npos, *option << " is not an option of " << script);
        }
    }
}

} // namespace

TEST_SUITE("distribute readme") {

TEST_CASE("the students' README and LISEZMOI: their tree, their commands, no solutions") {
    const fs::path tree = raylab::test::scratchPath("raylab-distribute-readme");
    fs::remove_all(tree);
    const fs::path output = raylab::test::scratchPath("raylab-distribute-readme.txt");
    const auto distributed = raylab::test::runProgram({RAYLAB_PROGRAM, "distribute", tree.string(), "--lang", "en"}, output);
    REQUIRE_MESSAGE(distributed.status == 0, distributed.output);
    for (const char* name : {"README.md", "LISEZMOI.md"}) {
        const std::string readme = readFile(tree / name);
        REQUIRE_MESSAGE(!readme.empty(), name);
        CHECK_MESSAGE(readme.find("solutions") == std::string::npos, name << ":\n" << readme);
        CHECK_MESSAGE(readme.find("out/reference") == std::string::npos, name << ":\n" << readme);
        // Every lab's handout, and every link, is a file of the tree.
        for (const raylab::grader::LabDescription& lab : raylab::grader::loadLabCatalog(fs::path(RAYLAB_SOURCE_DIR) / "labs").labs)
            CHECK_MESSAGE(readme.find("](labs/" + lab.id + "/README") != std::string::npos, name << ": " << lab.id);
        CHECK_MESSAGE(readme.find("|---|---|---|\n| 1 | [") != std::string::npos, name << ": the labs' table"); // one table
        const std::regex link(R"(\]\(([^)#]+)\))");
        int links = 0;
        for (std::sregex_iterator it(readme.begin(), readme.end(), link), end; it != end; ++it, ++links)
            CHECK_MESSAGE(fs::exists(tree / (*it)[1].str()), name << ": " << (*it)[1]);
        CHECK(links >= 8);
        const auto commands = fencedCommands(readme);
        CHECK(commands.size() >= 5); // setup, the workflow, lab, grade, report
        for (const auto& command : commands) checkCommand(tree, command, name);
        // The build command of the README is the one distribute prints.
        const std::string build = "scripts/setup.sh && cmake --workflow --preset ";
        const std::size_t at = readme.find(build);
        REQUIRE(at != std::string::npos);
        const std::string preset = readme.substr(at + build.size(), readme.find('\n', at) - at - build.size());
        CHECK_MESSAGE(distributed.output.find(build + preset) != std::string::npos, distributed.output);
        // Windows: the workflow preset it names is one of the tree's (vcpkg.json is a link, above).
        const std::string windows = "cmake --workflow --preset windows-figures";
        CHECK_MESSAGE(readme.find(windows) != std::string::npos, name);
        const std::vector<std::string> presets = workflowPresets(tree);
        CHECK(std::find(presets.begin(), presets.end(), "windows-figures") != presets.end());
    }
    CHECK(readFile(tree / "README.md").find("[LISEZMOI.md](LISEZMOI.md)") != std::string::npos);
    CHECK(readFile(tree / "LISEZMOI.md").find("[docs/glossaire.md](docs/glossaire.md)") != std::string::npos);
    // The French pages a student reads are in the tree, and LISEZMOI.md links them; each French
    // handout's "tous les TP" leads to LISEZMOI.md's table of the labs ("## Les TP": #les-tp).
    for (const char* page : {"docs/grading.fr.md", "docs/conventions.fr.md", "docs/glossaire.md"}) {
        CHECK_MESSAGE(fs::is_regular_file(tree / page), page);
        CHECK_MESSAGE(readFile(tree / "LISEZMOI.md").find(std::string("](") + page + ")") != std::string::npos, page);
    }
    CHECK(readFile(tree / "LISEZMOI.md").find("\n## Les TP\n") != std::string::npos);
    for (const raylab::grader::LabDescription& lab : raylab::grader::loadLabCatalog(fs::path(RAYLAB_SOURCE_DIR) / "labs").labs)
        CHECK_MESSAGE(readFile(tree / "labs" / lab.id / "README.fr.md").find("](../../LISEZMOI.md#les-tp)") != std::string::npos,
                      lab.id << ": its French handout links LISEZMOI.md#les-tp");
    fs::remove_all(tree);
    fs::remove(output);
}

}
