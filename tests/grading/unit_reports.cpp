// The reports say the same as the grade: Gradescope's JSON, JUnit XML and the HTML page.
#include "support/files.h"
#include "support/needs.h"
#include "support/run_program.h"
#include "grader/course/glossary_links.h"
#include "grader/course/grade_reports.h"
#include "grader/course/submission.h"
#include "grader/sandbox/process.h"
#include "src/messages.h"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <fstream>

using namespace raylab;
using namespace raylab::grader;
namespace fs = std::filesystem;

namespace {

using raylab::test::ProgramRun;
using raylab::test::readFile;
using raylab::test::runProgram;

GradeResult sampleResult() {
    GradeResult r;
    r.title = "sample <grade>";
    r.checks.push_back({2, "generateRay: corners", false, "expected (0, 0, 1), got (0, 0, -1). Hint: v & u", 0., 3.});
    r.checks.push_back({2, "updateViewport: height", true, "", 2., 2.});
    FigureOutcome f;
    f.id = "lab2_directions";
    f.lab = 2;
    f.passed = false;
    f.reason = "12 pixels differ";
    f.diagnosis = "your image matches 'v flipped'";
    f.maxPoints = 4.;
    f.verdict.width = 2;
    f.verdict.height = 1;
    f.verdict.error = {0.f, 9.f};
    r.figures.push_back(f);
    for (int lab = 1; lab <= 5; ++lab) r.labs.push_back({lab, lab == 2 ? 2. : 0., lab == 2 ? 9. : 0., {}});
    r.problems.push_back("an agent crashed");
    return r;
}

} // namespace

TEST_SUITE("reports") {

TEST_CASE("results.json is Gradescope's format, item by item") {
    const fs::path folder = raylab::test::scratchPath("raylab-report-test");
    fs::remove_all(folder);
    const ReferenceSet references;
    writeReports(sampleResult(), references, folder);
    const nlohmann::json j = nlohmann::json::parse(readFile(folder / "results.json"));
    CHECK(j["score"] == 2.);
    CHECK(j["extra_data"]["max_score"] == 9.);
    CHECK(j["tests"][0]["visibility"] == "visible");
    CHECK(j["stdout_visibility"] == "visible");
    REQUIRE(j["tests"].size() == 3);
    CHECK(j["tests"][0]["name"] == "lab2: generateRay: corners");
    CHECK(j["tests"][0]["status"] == "failed");
    CHECK(j["tests"][0]["max_score"] == 3.);
    CHECK(j["tests"][1]["status"] == "passed");
    CHECK(j["tests"][2]["output"].get<std::string>().find("v flipped") != std::string::npos);
    CHECK(j["output"].get<std::string>().find("crashed") != std::string::npos);
}

TEST_CASE("junit.xml has a test case per item and escapes the text") {
    const fs::path folder = raylab::test::scratchPath("raylab-report-test-junit");
    fs::remove_all(folder);
    writeReports(sampleResult(), ReferenceSet{}, folder);
    const std::string xml = readFile(folder / "junit.xml");
    CHECK(xml.find("<testsuite name=\"lab2\" tests=\"3\" failures=\"2\">") != std::string::npos);
    CHECK(xml.find("Hint: v &amp; u") != std::string::npos);
    CHECK(xml.find("sample &lt;grade&gt;") != std::string::npos);
}

TEST_CASE("index.html shows the score, the verdicts, the hints and the heat map") {
    const fs::path folder = raylab::test::scratchPath("raylab-report-test-html");
    fs::remove_all(folder);
    writeReports(sampleResult(), ReferenceSet{}, folder);
    const std::string html = readFile(folder / "index.html");
    CHECK(html.find("2 / 9") != std::string::npos);
    CHECK(html.find("your image matches &apos;v flipped&apos;") != std::string::npos);
    CHECK(html.find("images/lab2_directions.diff.png") != std::string::npos);
    CHECK(fs::exists(folder / "images" / "lab2_directions.diff.png"));
}

TEST_CASE("the console links each term of the glossary once, at its first use, in the reader's language") {
    GradeResult r = sampleResult();
    r.figures[0].reason = "12 pixels differ by more than 1 LSB, up to 9 LSB";
    FigureOutcome noisy = r.figures[0];
    noisy.id = "lab5_antialiased";
    noisy.reason = "too noisy: RMSE 3.1 LSB";
    r.figures.push_back(noisy);
    const Language before = language();
    setLanguage(Language::En);
    const std::string english = terminalSummary(r);
    CHECK_MESSAGE(english.find("up to 9 LSB (see docs/glossary.md#lsb)\n") != std::string::npos, english);
    CHECK_MESSAGE(english.find("RMSE 3.1 LSB (see docs/glossary.md#rmse)\n") != std::string::npos, english);
    CHECK_MESSAGE(english.find("#lsb") == english.rfind("#lsb"), english); // once per run
    setLanguage(Language::Fr);
    const std::string french = terminalSummary(r);
    CHECK_MESSAGE(french.find("(voir docs/glossaire.md#lsb)") != std::string::npos, french);
    // Two new terms on one line share one parenthesis; a longer word is not the term.
    setLanguage(Language::En);
    CHECK(withGlossaryLinks("RMSE 2 LSB\nLSBs and NaNs\nNaN") ==
          "RMSE 2 LSB (see docs/glossary.md#lsb, docs/glossary.md#rmse)\nLSBs and NaNs\nNaN (see docs/glossary.md#nan)");
    setLanguage(before);
}

TEST_CASE("a build's problem says the cause a person acts on first, in place of the build tools' words, in the reader's "
          "language") {
    const Language before = language();
    setLanguage(Language::En);
    const std::string memory = buildProblem(
        {"[ 50%] Building CXX object sphere_geometry.cpp.o\nvirtual memory exhausted: Cannot allocate memory\n"
         "g++: fatal error: Killed signal terminated program cc1plus\ncompilation terminated.\n"
         "gmake[2]: *** [CMakeFiles/lab3.dir/sphere_geometry.cpp.o] Error 1\n",
         "", 0});
    CHECK_MESSAGE(memory.rfind("the compiler ran out of memory (a file that expands too much?)\n", 0) == 0, memory);
    CHECK(memory.find("ran out of memory") == memory.rfind("ran out of memory")); // said once
    for (const char* noise : {"virtual memory", "Killed signal", "gmake"}) CHECK_MESSAGE(memory.find(noise) == std::string::npos, memory);

    // The guard's words for a compiler it stopped: a cause, first, before the errors it printed until then.
    const std::string time = buildProblem({"a.cpp:5:9: error: 'y' was not declared\n"
                                           "raylab-build-guard: time: labs/lab3_sphere/sphere_geometry.cpp\n", "", 0});
    CHECK_MESSAGE(time.rfind("compiling labs/lab3_sphere/sphere_geometry.cpp: the compiler ran past its time limit", 0) == 0, time);
    CHECK(time.find("a.cpp:5:9: error: 'y' was not declared") != std::string::npos);
    CHECK_MESSAGE(buildProblem({"raylab-build-guard: killed: a.cpp\n", "", 0}).rfind("compiling a.cpp: the compiler was killed, most "
                                                                                   "likely out of memory", 0) == 0, time);
    const std::string big = buildProblem({"g++: internal compiler error: File size limit exceeded signal terminated program as\n", "", 0});
    CHECK_MESSAGE(big.find("the compiler stopped at the 32 MB limit on each file it writes") != std::string::npos, big);

    // A gigabyte of errors: the first and the last kept, the cut said, the first error still there.
    const KeptOutput cut{"a.cpp:1:2: error: 'x' was not declared\n", "z.cpp:9:1: error: expected ';'\n", 1073612345};
    const std::string many = buildProblem(cut);
    CHECK_MESSAGE(many.rfind("the compiler's output was cut to 128 KB (1,073,612,345 bytes left out)", 0) == 0, many);
    CHECK(many.find("a.cpp:1:2: error: 'x' was not declared") != std::string::npos);
    CHECK(many.find("z.cpp:9:1: error: expected ';'") != std::string::npos);
    setLanguage(Language::Fr);
    const std::string french = buildProblem(cut);
    CHECK_MESSAGE(french.find("1\u00A0073\u00A0612\u00A0345 octets omis") != std::string::npos, french);
    CHECK_MESSAGE(buildProblem({"virtual memory exhausted\n", "", 0}).find("le compilateur a manqué de mémoire") != std::string::npos,
                  french);
    setLanguage(before);
}

TEST_CASE("every term the console links has its section in both glossaries") {
    for (const Language language : {Language::En, Language::Fr}) {
        const fs::path glossary = fs::path(RAYLAB_SOURCE_DIR) / tr(language, "glossary.file");
        REQUIRE_MESSAGE(fs::is_regular_file(glossary), glossary);
        const std::string text = readFile(glossary);
        for (const auto& [term, anchor] : glossaryTerms()) {
            CHECK_MESSAGE(text.find("<a id=\"" + anchor + "\"></a>\n## ") != std::string::npos, glossary << ": " << anchor);
            CHECK_MESSAGE(text.find(term) != std::string::npos, glossary << ": " << term);
        }
    }
}

} // TEST_SUITE

// Its own suite: skipped without python3 (support/needs.h).
TEST_SUITE("reports xml parser") {

TEST_CASE("junit.xml parses with a real XML parser when a message holds control characters and bytes that are not UTF-8") {
    const fs::path folder = raylab::test::scratchPath("raylab-report-test-junit-control");
    fs::remove_all(folder);
    GradeResult r = sampleResult();
    r.title = "raylab grade bad\xFEname";
    r.checks[0].message = "the agent threw: \x1B[31mred\x1B[0m\x01 \xFF\xEF\xBF\xBF end";
    writeReports(r, ReferenceSet{}, folder);
    // Python's xml.etree (expat), given an argument vector: it stops at the first character XML 1.0 forbids.
    const fs::path python = raylab::test::neededProgram("python3", "python3");
    if (python.empty()) return;
    const std::string script = "import sys, xml.etree.ElementTree as E\n"
                               "root = E.parse(sys.argv[1]).getroot()\n"
                               "sys.stdout.buffer.write(root.get('name').encode() + b'|' + root.find('.//failure').text.encode())\n";
    const ProgramRun parsed = runProgram({python.string(), "-c", script, (folder / "junit.xml").string()}, folder / "parsed.txt");
    CHECK_MESSAGE(parsed.status == 0, parsed.output);
    CHECK(parsed.output == "raylab grade bad\\xFEname|the agent threw: \\x1B[31mred\\x1B[0m\\x01 \\xFF\\xEF\\xBF\\xBF end");
    // The same words in results.json and on the terminal: no escape sequence, no U+FFFD.
    const nlohmann::json j = nlohmann::json::parse(readFile(folder / "results.json"));
    CHECK(j["tests"][0]["output"] == "the agent threw: \\x1B[31mred\\x1B[0m\\x01 \\xFF\\xEF\\xBF\\xBF end");
    CHECK(terminalSummary(r).find("the agent threw: \\x1B[31mred") != std::string::npos);
}

} // TEST_SUITE
