// The command line speaks the reader's language: `raylab --help`, every command's help, the student
// commands' output and the argument errors, CLI11's own included, are French with --lang fr and hold
// none of the English sentences.
#include "grader/lab_catalog.h"
#include "support/scene_files.h"
#include "src/messages.h"
#include "support/run_program.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <optional>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using namespace raylab;

namespace {

// A file name of this run's own in the temporary folder.
std::filesystem::path scratchFile(const std::string& name) {
    return std::filesystem::temp_directory_path() / ("raylab-cli-" + std::to_string(std::random_device{}()) + "-" + name);
}

// Runs raylab with `args`: its output; `fails` tells whether it must exit with an error (nullopt:
// either, for what depends on the labs the student has written).
std::string run(std::vector<std::string> args, std::optional<bool> fails = false) {
    args.insert(args.begin(), RAYLAB_PROGRAM);
    const auto output = scratchFile("output.txt");
    const test::ProgramRun done = test::runProgram(args, output);
    std::filesystem::remove(output);
    if (fails) CHECK_MESSAGE((done.status != 0) == *fails, done.status << ": " << done.output);
    CHECK_MESSAGE(done.status < 128, done.output); // not killed by a signal
    return done.output;
}

bool has(const std::string& output, const std::string& text) { return output.find(text) != std::string::npos; }

// Each description is in the output in French and not in English.
void checkDescriptions(const std::string& output, const std::vector<std::string>& ids) {
    for (const std::string& id : ids) {
        CHECK_MESSAGE(has(output, tr(Language::Fr, id)), id << " in\n" << output);
        CHECK_MESSAGE(!has(output, tr(Language::En, id)), id << " in\n" << output);
    }
}

// CLI11's English, which a French reader must never see.
const std::vector<std::string> kCli11English{"Usage:", "Print this help message", "Run with --help",
                                             "not expected", "is required", "not in range", "Could not convert",
                                             "Subcommands:", "Positionals:", "At Most", "required but received",
                                             // its value types (TEXT:DIR, INT in [1 - 100]), the words alone
                                             "TEXT:", "TEXT ", "INT:", "INT ", ":DIR", "DIR/", "FILE"};

void checkNoCli11English(const std::string& output) {
    for (const std::string& english : kCli11English) CHECK_MESSAGE(!has(output, english), english << " in\n" << output);
}

// The words of a text, lower case: its pieces between spaces and punctuation that are ASCII letters only.
// A piece with a digit, '_', '/', '.', '-', '<', '=' ... inside (a path, an id, an option) is no word.
std::vector<std::string> wordsOf(const std::string& original) {
    const std::string nbsp = "\u00A0"; // French spacing: a blank too
    std::string text;
    for (std::size_t from = 0, at; from < original.size(); from = at + (at < original.size() ? nbsp.size() : 0)) {
        at = std::min(original.find(nbsp, from), original.size());
        text += original.substr(from, at - from) + " ";
    }
    std::vector<std::string> words;
    std::string piece;
    const auto flush = [&] {
        while (!piece.empty() && (piece.back() == '.' || piece.back() == '-')) piece.pop_back(); // a sentence's end
        if (!piece.empty() && std::all_of(piece.begin(), piece.end(), [](unsigned char c) { return std::isalpha(c); })) {
            std::transform(piece.begin(), piece.end(), piece.begin(), [](unsigned char c) { return char(std::tolower(c)); });
            words.push_back(piece);
        }
        piece.clear();
    };
    for (const char c : text) {
        if (std::isspace(static_cast<unsigned char>(c)) || std::string_view(",;:()[]{}\"'`!?|").find(c) != std::string_view::npos)
            flush();
        else piece += c;
    }
    flush();
    return words;
}

// The English catalogue's sentence words (5 letters or more, outside its {placeholders}) that French
// never uses, not even inside a word of fr.toml: a French output holding one holds English.
const std::set<std::string>& englishOnlyWords() {
    static const std::set<std::string> words = [] {
        std::string french;
        for (const auto& [id, text] : messageCatalogue(Language::Fr)) french += text + "\n";
        std::transform(french.begin(), french.end(), french.begin(), [](unsigned char c) { return char(std::tolower(c)); });
        std::set<std::string> english;
        for (const auto& [id, text] : messageCatalogue(Language::En)) {
            std::string sentence;
            for (std::size_t k = 0, depth = 0; k < text.size(); ++k) { // {name} and {n|one|other} are no words
                depth += text[k] == '{';
                if (depth == 0) sentence += text[k];
                if (text[k] == '}' && depth > 0) --depth, sentence += ' ';
            }
            for (const std::string& word : wordsOf(sentence))
                if (word.size() >= 5 && french.find(word) == std::string::npos) english.insert(word);
        }
        return english;
    }();
    return words;
}

// The English-only words found in `output` (empty when it is all French), but the commands' names.
std::set<std::string> englishIn(const std::string& output, const std::set<std::string>& names = {}) {
    std::set<std::string> found;
    for (const std::string& word : wordsOf(output))
        if (englishOnlyWords().count(word) && !names.count(word)) found.insert(word);
    return found;
}

std::string joined(const std::set<std::string>& words) {
    std::string text;
    for (const std::string& w : words) text += (text.empty() ? "" : ", ") + w;
    return text;
}

void checkAllFrench(const std::string& what, const std::string& output, const std::set<std::string>& names = {}) {
    const std::set<std::string> english = englishIn(output, names);
    CHECK_MESSAGE(english.empty(), what << ": English words " << joined(english) << " in\n" << output);
    checkNoCli11English(output);
}

// The commands as the program lists them (its help's "Subcommands:" in English), with their own
// subcommands: {"grade"}, {"autograder", "github"} ...
std::vector<std::vector<std::string>> commandsOf(std::vector<std::string> path) {
    std::vector<std::string> args = path;
    args.insert(args.end(), {"--help", "--lang", "en"});
    std::istringstream help(run(args));
    std::vector<std::vector<std::string>> commands;
    bool inList = false;
    for (std::string line; std::getline(help, line);) {
        if (line == "Subcommands:") inList = true;
        else if (line.empty()) inList = false;
        else if (inList && line.size() > 2 && line.rfind("  ", 0) == 0 && line[2] != ' ') {
            std::vector<std::string> command = path;
            command.push_back(line.substr(2, line.find(' ', 2) - 2));
            commands.push_back(command);
            for (std::vector<std::string>& sub : commandsOf(command)) commands.push_back(std::move(sub));
        }
    }
    return commands;
}

} // namespace

TEST_SUITE("command line language") {

TEST_CASE("raylab --help in French: the program, the student commands, the headings") {
    const std::string help = run({"--lang", "fr", "--help"});
    CHECK_MESSAGE(has(help, "Utilisation"), help);
    CHECK_MESSAGE(has(help, "Affiche cette aide et quitte"), help);
    CHECK_MESSAGE(has(help, "Commandes"), help);
    checkDescriptions(help, {"cli.lang", "cli.figures", "cli.lab", "cli.render", "cli.grade", "cli.report"});
    CHECK_MESSAGE(!has(help, "This program is the"), help);
    checkNoCli11English(help);
}

TEST_CASE("the English-only words are found: the test can fail") {
    CHECK(englishOnlyWords().count("yardstick") == 1); // in cli.bench
    CHECK(englishIn("enseignants\u00A0: écrit l'arborescence des étudiants").empty());
    const std::set<std::string> found = englishIn("  bench   primary rays per second, beside a hand-written yardstick");
    const std::set<std::string> expected{"beside", "primary", "yardstick"}; // "second": in fr.toml ("seconde")
    CHECK_MESSAGE(found == expected, joined(found));
    CHECK(englishIn("out/grade-build lab3_cosine --build-dir").empty()); // paths, ids and options are no words
}

TEST_CASE("raylab --help and every command's --help in French: no English word") {
    const std::vector<std::vector<std::string>> commands = commandsOf({});
    // The app's own list: the student commands and the instructors', with their subcommands.
    for (const char* command : {"grade", "report", "distribute", "autograder", "bench"})
        CHECK_MESSAGE(std::count(commands.begin(), commands.end(), std::vector<std::string>{command}) == 1, command);
    CHECK(std::count(commands.begin(), commands.end(), std::vector<std::string>{"autograder", "github"}) == 1);
    std::set<std::string> names; // a command's name is no word: `raylab study antialiasing`
    for (const std::vector<std::string>& command : commands) names.insert(command.back());
    checkAllFrench("raylab --help", run({"--help", "--lang", "fr"}), names);
    for (std::vector<std::string> command : commands) {
        const std::string name = "raylab " + command.back() + " --help";
        command.insert(command.end(), {"--help", "--lang", "fr"});
        checkAllFrench(name, run(command), names);
    }
}

TEST_CASE("the student commands in French: no English word") {
    const auto out = scratchFile("out");
    const std::string folder = out.string();
    // Whichever labs are written (the students' tree runs this too): a stub or a picture, a grade.
    checkAllFrench("raylab lab 1", run({"lab", "1", "--out", folder, "--lang", "fr"}, std::nullopt));
    checkAllFrench("raylab lab 3", run({"lab", "3", "--out", folder, "--lang", "fr"}, std::nullopt));
    checkAllFrench("raylab figures", run({"figures", "--out", folder, "--lang", "fr"}, std::nullopt));
    checkAllFrench("raylab grade", run({"grade", "--report", folder + "/report", "--lang", "fr"}, std::nullopt));
    checkAllFrench("raylab report", run({"report", "--out", folder + "/kit", "--lang", "fr"}, std::nullopt));
    std::filesystem::remove_all(out);
}

TEST_CASE("raylab grade in French on written labs, right and wrong: no English word") {
    // The instructors' tree has the reference agent and one agent per classic mistake: their hints.
    const std::filesystem::path bin = std::filesystem::path(RAYLAB_PROGRAM).parent_path();
    const auto report = scratchFile("report");
    int graded = 0;
    for (const auto& entry : std::filesystem::directory_iterator(bin)) {
        const std::string name = entry.path().filename().string();
        if (name != "raylab-agent-reference" && name.rfind("raylab-mistake-", 0) != 0) continue;
        ++graded;
        checkAllFrench("raylab grade --agent " + name,
                       run({"grade", "--agent", entry.path().string(), "--report", report.string(), "--lang", "fr"}, std::nullopt));
    }
    std::filesystem::remove_all(report);
    MESSAGE(graded << " agents graded in French");
}

TEST_CASE("raylab grade --help in French: every option's description") {
    const std::string help = run({"grade", "--help", "--lang", "fr"});
    checkDescriptions(help, {"cli.grade", "cli.grade_labs", "cli.grade_images", "cli.grade_report", "cli.grade_lab",
                             "cli.grade_item", "cli.grade_references", "cli.grade_timeout", "cli.grade_build_dir",
                             "cli.threads", "cli.scenes"});
    checkNoCli11English(help);
}

TEST_CASE("the student commands' options are described in French") {
    checkDescriptions(run({"--lang", "fr", "figures", "--help"}),
                      {"cli.figures_out", "cli.figures_only", "cli.impl", "cli.threads"});
    checkDescriptions(run({"--lang", "fr", "lab", "--help"}), {"cli.lab_number", "cli.lab_out"});
    checkDescriptions(run({"--lang", "fr", "render", "--help"}), {"cli.render_file", "cli.render_out"});
    checkDescriptions(run({"--lang", "fr", "report", "--help"}), {"cli.report_out", "cli.report_pdf"});
}

TEST_CASE("the options' value types are named in French") {
    const std::string help = run({"--lang", "fr", "grade", "--help"});
    CHECK_MESSAGE(has(help, "TEXTE:DOSSIER"), help);  // --labs
    CHECK_MESSAGE(has(help, "ENTIER:0..1024"), help); // --threads
    CHECK_MESSAGE(has(help, "ENTIER:POSITIF"), help); // --lab
    checkNoCli11English(help);
    const std::string bench = run({"--lang", "fr", "bench", "--help"});
    CHECK_MESSAGE(has(bench, "--repeats ENTIER:1..100 "), bench); // the type once, then the range
    CHECK_MESSAGE(!has(bench, "ENTIER:ENTIER"), bench);
    checkNoCli11English(run({"--lang", "fr", "report", "--help"}));
    checkNoCli11English(run({"--lang", "fr", "render", "--help"}));
    const std::string english = run({"--lang", "en", "grade", "--help"});
    CHECK_MESSAGE(has(english, "TEXT:DIR"), english);
}

TEST_CASE("argument errors in French keep the option's name and the value") {
    const std::string nbsp = "\u00A0";
    struct Case {
        std::vector<std::string> args;
        std::string french;
    };
    // The course's labs, and a number none has (the catalogue says which: no list of our own).
    const std::vector<int> numbers = raylab::grader::loadLabCatalog(raylab::test::kLabsDir).numbers();
    std::string listed;
    for (int n : numbers) listed += " " + std::to_string(n);
    const std::string none = std::to_string(*std::max_element(numbers.begin(), numbers.end()) + 1);
    // --lang last (it may stand anywhere), but before an option left without its value.
    const std::vector<Case> cases{
        {{"grade", "--bogus", "--lang", "fr"}, "--bogus n'est pas une option de raylab grade" + nbsp + "; ses options" + nbsp + ": "},
        {{"grade", "extra", "words", "--lang", "fr"}, "inattendu ici" + nbsp + ": extra words"},
        {{"--lang", "fr", "grade", "--lab"}, "--lab attend une valeur"},
        {{"grade", "--lab", "two", "--lang", "fr"}, "--lab" + nbsp + ": two n'est pas un nombre positif"},
        {{"report", "--pdf=maybe", "--lang", "fr"}, "--pdf" + nbsp + ": «" + nbsp + "maybe" + nbsp + "» n'est pas une valeur valide"},
        {{"lab", none, "--lang", "fr"}, "TP " + none + nbsp + ": ce TP n'existe pas (les TP sont" + listed + ")"},
        {{"render", "--lang", "fr"}, "FICHIER est obligatoire"},
        {{"report", "--out", "a", "--out", "b", "--lang", "fr"}, "--out apparaît 2 fois" + nbsp + "; le maximum est 1"},
        {{"figures", "--impl", "mine", "--lang", "fr"}, "--impl" + nbsp + ": mine n'est pas l'une des valeurs {student,reference}"},
        {{"grade", "--labs", "/nonexistent/labs", "--lang", "fr"}, "ce dossier n'existe pas" + nbsp + ": /nonexistent/labs"},
        {{"--lang", "fr"}, "il faut une commande"},
        {{"frobnicate", "--lang", "fr"}, "commande inconnue «" + nbsp + "frobnicate" + nbsp + "»"},
        {{"figures", "--threads", "5000", "--lang", "fr"}, "5000 fils, c'est plus que raylab n'en lance" + nbsp + ": au plus 1024"},
        {{"grade", "--timeout", "nan", "--lang", "fr"}, "«" + nbsp + "nan" + nbsp + "» n'est pas une limite de temps"},
        {{"bench", "--repeats", "0", "--lang", "fr"}, "--repeats" + nbsp + ": 0 n'est pas entre 1 et 100"},
        {{"render", "/no/such.toml", "--lang", "fr"}, "/no/such.toml" + nbsp + ": ce fichier de scène n'existe pas"},
    };
    for (const Case& c : cases) {
        const std::string output = run(c.args, true);
        CHECK_MESSAGE(has(output, c.french), output);
        CHECK_MESSAGE(has(output, "raylab" + nbsp + ": erreur" + nbsp + ": "), output);
        checkNoCli11English(output);
    }
}

TEST_CASE("raylab render says what it renders in French") {
    const auto out = scratchFile("render.png");
    // Its first line, whether the student's lab 1 is written (the render succeeds) or not (it fails).
    const std::string output = run({"render", raylab::test::figureSceneFile("lab1_gradient").string(), "--out", out.string(), "--lang", "fr"}, std::nullopt);
    std::filesystem::remove(out);
    CHECK_MESSAGE(has(output, "lab1_gradient.toml\u00A0: 600 x 400, "), output);
    CHECK_MESSAGE(has(output, ", 1 échantillon par pixel (échantillonneur "), output);
    CHECK_MESSAGE(!has(output, "samples per pixel"), output);
}

TEST_CASE("an option the command does not have is named, beside the ones it has, in the command line's order") {
    // As `raylab render` has it: `raylab grade` writes its report with --report.
    const std::string output = run({"grade", "--out", "build/grade", "--lang", "en"}, true);
    CHECK_MESSAGE(has(output, "raylab: error: --out is not an option of raylab grade; its options: "), output);
    CHECK_MESSAGE(has(output, "--report"), output);
    CHECK_MESSAGE(!has(output, "--help,"), output);
    const std::string nested = run({"study", "antialiasing", "--frobnicate=3", "--lang", "en"}, true);
    CHECK_MESSAGE(has(nested, "--frobnicate is not an option of raylab study antialiasing; "), nested);
    // Words of any bytes are quoted as text: an escape sequence never reaches the terminal.
    const std::string odd = run({"grade", "--\x1b[31mred", "--lang", "en"}, true);
    CHECK_MESSAGE(has(odd, "raylab: error: --\\x1B[31mred is not an option of raylab grade"), odd);
    const std::string command = run({"gr\x1b[2Jade", "--lang", "en"}, true);
    CHECK_MESSAGE(has(command, "gr\\x1B[2Jade"), command);
    const std::string both = odd + command;
    CHECK_MESSAGE(!has(both, "\x1b"), both);
}

TEST_CASE("in English, the same errors are English") {
    const std::string output = run({"grade", "--bogus", "--lang", "en"}, true);
    CHECK_MESSAGE(has(output, "raylab: error: --bogus is not an option of raylab grade; its options: "), output);
    CHECK_MESSAGE(has(output, "Run with --help for more information."), output);
}

}
