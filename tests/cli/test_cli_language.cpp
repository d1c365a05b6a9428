// The command line speaks the reader's language: `raylab --help`, the student commands' help and the
// argument errors, CLI11's own included, are French with --lang fr and hold none of the English sentences.
#include "src/messages.h"
#include "support/run_program.h"

#include <doctest/doctest.h>

#include <filesystem>
#include <optional>
#include <random>
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
    // --lang last (it may stand anywhere), but before an option left without its value.
    const std::vector<Case> cases{
        {{"grade", "--bogus", "--lang", "fr"}, "inattendu ici" + nbsp + ": --bogus"},
        {{"--lang", "fr", "grade", "--lab"}, "--lab attend une valeur"},
        {{"grade", "--lab", "two", "--lang", "fr"}, "--lab" + nbsp + ": two n'est pas un nombre positif"},
        {{"report", "--pdf=maybe", "--lang", "fr"}, "--pdf" + nbsp + ": «" + nbsp + "maybe" + nbsp + "» n'est pas une valeur valide"},
        {{"lab", "9", "--lang", "fr"}, "TP 9" + nbsp + ": ce TP n'existe pas (les TP sont 1 2 3 4 5)"},
        {{"render", "--lang", "fr"}, "FICHIER est obligatoire"},
        {{"report", "--out", "a", "--out", "b", "--lang", "fr"}, "--out apparaît 2 fois" + nbsp + "; le maximum est 1"},
        {{"figures", "--impl", "mine", "--lang", "fr"}, "--impl" + nbsp + ": mine n'est pas l'une des valeurs {student,reference}"},
        {{"grade", "--labs", "/nonexistent/labs", "--lang", "fr"}, "ce dossier n'existe pas" + nbsp + ": /nonexistent/labs"},
        {{"--lang", "fr"}, "il faut une commande"},
        {{"frobnicate", "--lang", "fr"}, "commande inconnue «" + nbsp + "frobnicate" + nbsp + "»"},
        {{"figures", "--threads", "5000", "--lang", "fr"}, "5000 fils, c'est plus que raylab n'en lance" + nbsp + ": au plus 1024"},
        {{"grade", "--timeout", "nan", "--lang", "fr"}, "«" + nbsp + "nan" + nbsp + "» n'est pas une limite de temps"},
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
    const std::string output = run({"render", std::string(RAYLAB_SCENES_DIR) + "/lab1_gradient.toml", "--out", out.string(), "--lang", "fr"}, std::nullopt);
    std::filesystem::remove(out);
    CHECK_MESSAGE(has(output, "lab1_gradient.toml\u00A0: 600 x 400, "), output);
    CHECK_MESSAGE(has(output, ", 1 échantillon par pixel (échantillonneur "), output);
    CHECK_MESSAGE(!has(output, "samples per pixel"), output);
}

TEST_CASE("in English, the same errors are English") {
    const std::string output = run({"grade", "--bogus", "--lang", "en"}, true);
    CHECK_MESSAGE(has(output, "raylab: error: not expected here: --bogus"), output);
    CHECK_MESSAGE(has(output, "Run with --help for more information."), output);
}

}
