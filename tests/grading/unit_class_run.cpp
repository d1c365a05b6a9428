// The class ledger's pieces: a safe folder name for any student name, one to one; a printable name,
// one to one too; CSV cells that a real CSV reader reads back as they were, formulas defused; the
// problems cell, short and whole characters.
#include "grader/course/class_run.h"
#include "grader/course/run_scratch.h"
#include "grader/course/submission.h"
#include "src/csv.h"
#include "src/text.h"
#include "src/atomic_file.h"
#include "support/files.h"
#include "support/read_csv.h"
#include "support/small_disk.h"

#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>
#include <utility>
#include <vector>
#if defined(__unix__) || defined(__APPLE__)
#include <csignal>
#include <cstdio>
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>
#endif

namespace fs = std::filesystem;
using raylab::printableName;
using raylab::grader::removeAbandonedScratch;
using raylab::grader::RunScratch;
using raylab::grader::problemSummary;
using raylab::grader::safeStudentName;

namespace {

const std::vector<std::string> kHostileNames{
    "alice", "Alice", "x$(touch PWNED)", "back`tick`", "double\"quote", "single'quote", "with space", "-leading-dash",
    ".hidden", "..", "ünïcödé 名前", "a,b", "new\nline", "grades.csv", "build", "students", "%41", "A", "%", "a%2Cb",
    "tab\there", std::string("nul\0byte", 8), std::string(300, 'x'), std::string(300, 'x') + "y", std::string(200, '%'),
    std::string(200, '%') + "~"};

} // namespace

TEST_SUITE("class run") {

TEST_CASE("safe student names: one to one, file names of plain characters that no tool reads as an option") {
    std::set<std::string> seen;
    for (const std::string& name : kHostileNames) {
        const std::string safe = safeStudentName(name);
        CAPTURE(printableName(name));
        CAPTURE(safe);
        CHECK(seen.insert(safe).second);
        CHECK(!safe.empty());
        CHECK(safe.size() <= 160);
        CHECK(safe.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-.%~") ==
              std::string::npos);
        CHECK(safe[0] != '-');
        CHECK(safe[0] != '.');
    }
    CHECK(safeStudentName("alice") == "alice"); // plain names stay readable
    CHECK(safeStudentName("a,b") == "a%2Cb");
    CHECK(safeStudentName("a%2Cb") == "a%252Cb");
}

TEST_CASE("printable names: one line of UTF-8, control characters and bytes that are not UTF-8 shown, one to one") {
    CHECK(printableName("new\nline") == "new\\nline");
    CHECK(printableName("tab\there\x01") == "tab\\there\\x01");
    CHECK(printableName("ünïcödé 名前 😀") == "ünïcödé 名前 😀");
    CHECK(printableName("bad\xFEname") == "bad\\xFEname");
    CHECK(printableName("bad\xFFname") == "bad\\xFFname");
    CHECK(printableName("esc\x1B[31m, del\x7F, csi\xC2\x9B") == "esc\\x1B[31m, del\\x7F, csi\\xC2\\x9B");
    CHECK(printableName("overlong\xC0\xAF, surrogate\xED\xA0\x80, cut\xE2\x82") ==
          "overlong\\xC0\\xAF, surrogate\\xED\\xA0\\x80, cut\\xE2\\x82");
    CHECK(printableName("nonchar\xEF\xBF\xBF") == "nonchar\\xEF\\xBF\\xBF");
    CHECK(printableName("back\\slash") == "back\\\\slash");
    // Two names never print alike: a byte and the text that shows it, U+FFFD and a bad byte.
    std::set<std::string> shown;
    for (const std::string& name : std::vector<std::string>{"bad\xFEname", "bad\xFFname", "bad\\xFEname", "bad\xEF\xBF\xBDname", "new\nline",
                                   "new\\nline", std::string("nul\0", 4), "nul\\x00"})
        CHECK_MESSAGE(shown.insert(printableName(name)).second, printableName(name));
}

TEST_CASE("printable names and messages: bidi controls and invisible characters shown as their bytes, so no name reverses "
          "the text after it or prints like another") {
    CHECK(printableName("\xE2\x80\xAEgnissim") == "\\xE2\\x80\\xAEgnissim"); // U+202E, would show "missing"
    for (const char* c : {"\xE2\x80\xAA", "\xE2\x80\xAB", "\xE2\x80\xAC", "\xE2\x80\xAD", "\xE2\x81\xA6", "\xE2\x81\xA7",
                          "\xE2\x81\xA8", "\xE2\x81\xA9", "\xE2\x80\x8E", "\xE2\x80\x8F", "\xD8\x9C", "\xE2\x80\x8B",
                          "\xE2\x80\x8C", "\xE2\x80\x8D", "\xE2\x81\xA0", "\xEF\xBB\xBF", "\xC2\xAD", "\xE2\x80\xA8",
                          "\xE2\x80\xA9", "\xEF\xB8\x8F", "\xF3\xA0\x80\x81", "\xE3\x85\xA4"}) {
        const std::string text = std::string("a") + c + "b";
        CAPTURE(printableName(text));
        std::string bytes;
        for (const char b : std::string(c)) {
            char hex[5];
            std::snprintf(hex, sizeof hex, "\\x%02X", static_cast<unsigned char>(b));
            bytes += hex;
        }
        CHECK(printableName(text) == "a" + bytes + "b");
        CHECK(raylab::printableText(text) == "a" + bytes + "b");
    }
    CHECK(printableName("visible: é ü 名前 ا 😀 \xE2\x80\x94") == "visible: é ü 名前 ا 😀 \xE2\x80\x94"); // an em dash stays
}

TEST_CASE("printable paths: a folder's newline and escape sequence shown as the names are, '/' between folders") {
    CHECK(raylab::printablePath(fs::path("class") / "new\nline\x1B[2J" / "gradient.cpp") == "class/new\\nline\\x1B[2J/gradient.cpp");
    CHECK(raylab::printablePath("plain/path") == "plain/path");
}

TEST_CASE("printable messages keep their lines and tabs, and are UTF-8 whatever the bytes") {
    CHECK(raylab::printableText("a\nb\tc\r\n") == "a\nb\tc\r\n");
    CHECK(raylab::printableText("\x1B[2Jcleared \xFE") == "\\x1B[2Jcleared \\xFE");
    CHECK(raylab::printableText("C:\\path") == "C:\\path");
}

TEST_CASE("CSV cells a spreadsheet would run as a formula read as text; numbers stay numbers") {
    const std::vector<std::string> cells{"=1+2*3", "=HYPERLINK(\"http://x\",\"y\")", "+1+1", "-1+1", "@SUM(A1)", "\tx",
                                         "\rx", "-", "-1.5", "+2", "3e-4", "-.5", "x=1", ""};
    const auto rows = raylab::test::readCsv(raylab::csvLine(cells));
    REQUIRE(rows.size() == 1);
    CHECK(rows[0] == std::vector<std::string>{"'=1+2*3", "'=HYPERLINK(\"http://x\",\"y\")", "'+1+1", "'-1+1", "'@SUM(A1)",
                                              "'\tx", "'\rx", "'-", "-1.5", "+2", "3e-4", "-.5", "x=1", ""});
}

TEST_CASE("CSV cells: a formula after a separator or a line break inside a cell defused too, so a spreadsheet that "
          "splits at ';' runs none") {
    const std::vector<std::string> cells{"H\xC3\xA9lo\xC3\xAFse;=1+1;", "x;=1+1;@SUM(2)", "a\n=3+3", "a,+b", "a\t-c",
                                         "a\r\n@d", "a; \"=e\"", "a;-1;+2.5", "a, b", "-", "x=1;y"};
    const auto rows = raylab::test::readCsv(raylab::csvLine(cells));
    REQUIRE(rows.size() == 1);
    CHECK(rows[0] == std::vector<std::string>{"H\xC3\xA9lo\xC3\xAFse;'=1+1;", "x;'=1+1;'@SUM(2)", "a\n'=3+3", "a,'+b",
                                              "a\t'-c", "a\r\n'@d", "a; \"'=e\"", "a;-1;+2.5", "a, b", "'-", "x=1;y"});
}

TEST_CASE("CSV cells holding ';' or a tab are quoted, as those holding ',': one cell whatever the separator") {
    CHECK(raylab::csvLine({"a;b", "c\td", "e,f", "g"}) == "\"a;b\",\"c\td\",\"e,f\",g\n");
}

TEST_CASE("CSV lines read back by a CSV reader as the cells they were written from") {
    const std::vector<std::string> cells{"plain", "a,b", "double\"quote", "new\nline", "", " spaced ", "crlf\r\nx"};
    const auto rows = raylab::test::readCsv(raylab::csvLine(cells) + raylab::csvLine({"1", "2"}));
    REQUIRE(rows.size() == 2);
    CHECK(rows[0] == cells);
    CHECK(rows[1] == std::vector<std::string>{"1", "2"});
    CHECK(raylab::csvLine({"a", "b"}) == "a,b\n");
}

TEST_CASE("problem summaries: the first line and three error lines, cut at a word, never inside a character") {
    CHECK(problemSummary("labs 3 4 do not build:\n\na.cpp:1: error: x\nb.cpp:2: error: y\nc.cpp:3: error: z\nd.cpp:4: error: w") ==
          "labs 3 4 do not build:\na.cpp:1: error: x\nb.cpp:2: error: y\nc.cpp:3: error: z");
    const std::string words = std::string(150, 'a') + " " + std::string(100, 'b');
    CHECK(problemSummary(words) == std::string(150, 'a') + " …");
    std::string accents; // 2 bytes a character, no space: cut at 200 bytes, between two characters
    for (int k = 0; k < 150; ++k) accents += "é";
    CHECK(problemSummary(accents) == accents.substr(0, 200) + " …");
    std::string shifted(1, 'x'), cut(1, 'x'); // byte 200 is inside an é: cut before it
    shifted += accents;
    cut += accents.substr(0, 198) + " …";
    CHECK(problemSummary(shifted) == cut);
    CHECK(problemSummary("") == "");
}

} // TEST_SUITE

#if defined(__unix__) || defined(__APPLE__)
TEST_SUITE("class run") {

TEST_CASE("scratch folders: a dead run's is removed; a live run's, and a folder that is no run's, are kept") {
    const fs::path temporary = raylab::test::scratchPath("raylab-unit-scratch");
    fs::remove_all(temporary);
    fs::create_directories(temporary / "raylab-class-not-a-run" / "inside"); // a user's or a test's folder
    fs::create_directories(temporary / "raylab-class-dead");
    std::ofstream(temporary / "raylab-class-dead" / ".raylab-run") << ""; // its holder is gone: no lock
    std::ofstream(temporary / "raylab-class-dead" / "agent.txt") << "left";
    fs::create_directories(temporary / "raylab-grade-dead");
    std::ofstream(temporary / "raylab-grade-dead" / ".raylab-run") << ""; // another kind of run
    {
        const RunScratch live("class"); // in the real temporary folder: its own, locked
        fs::create_directories(temporary / "raylab-class-live");
        fs::copy_file(live.path() / ".raylab-run", temporary / "raylab-class-live" / ".raylab-run");
        const int held = ::open((temporary / "raylab-class-live" / ".raylab-run").c_str(), O_RDONLY | O_CLOEXEC);
        REQUIRE(held >= 0);
        REQUIRE(::flock(held, LOCK_EX | LOCK_NB) == 0); // as a live run holds its mark
        const auto removed = removeAbandonedScratch(temporary, "class");
        CHECK(removed == std::vector<fs::path>{temporary / "raylab-class-dead"});
        CHECK(fs::exists(temporary / "raylab-class-live"));
        CHECK(fs::exists(temporary / "raylab-class-not-a-run" / "inside"));
        CHECK(fs::exists(temporary / "raylab-grade-dead"));
        CHECK(fs::exists(live.path()));
        ::close(held);
        CHECK(removeAbandonedScratch(temporary, "class") == std::vector<fs::path>{temporary / "raylab-class-live"});
        CHECK(fs::exists(live.path())); // still held by `live`
    }
    fs::remove_all(temporary);
}

// What the students share (the framework's build) is made once, before the first student to grade,
// and not at all by a run with nothing to grade; each step appends its line to one file.
TEST_CASE("a class run prepares once, before the first student it grades, and not when every student is graded") {
    const fs::path root = fs::temp_directory_path() / "raylab-unit-prepare";
    fs::remove_all(root);
    for (const char* name : {"alice", "bob"}) {
        fs::create_directories(root / "class" / name);
        std::ofstream(root / "class" / name / "gradient.cpp") << "// work\n";
    }
    const fs::path steps = root / "steps.txt";
    const auto append = [&](const std::string& line) { std::ofstream(steps, std::ios::app) << line << "\n"; };
    raylab::grader::ClassRunOptions options;
    options.classFolder = root / "class";
    options.out = root / "out";
    options.beforeFirstStudent = [&] { append("prepared"); };
    const auto grade = [&](const raylab::grader::StudentWork& work) {
        append(work.name);
        return raylab::grader::StudentRecord{work.name, {{"total", "1"}}};
    };
    REQUIRE(raylab::grader::runClass(options, grade) == 0);
    std::ifstream first(steps);
    CHECK(std::string(std::istreambuf_iterator<char>(first), {}) == "prepared\nalice\nbob\n");
    fs::remove(steps);
    REQUIRE(raylab::grader::runClass(options, grade) == 0); // both graded: nothing to prepare
    CHECK_FALSE(fs::exists(steps));
    fs::remove_all(root);
}

#if defined(__unix__) || defined(__APPLE__)
// grade-class holds StopSignals from before its run until its scratch folder is removed: a stop that
// comes before the run stops it before anyone is graded; one that comes after it kills nothing.
TEST_CASE("a stop signal while a command holds StopSignals: before the run, it stops the run; after it, nothing") {
    const fs::path root = raylab::test::freshFolder("raylab-unit-stop-signals");
    fs::create_directories(root / "class" / "alice");
    std::ofstream(root / "class" / "alice" / "gradient.cpp") << "// work\n";
    raylab::grader::ClassRunOptions options;
    options.classFolder = root / "class";
    options.out = root / "out";
    const auto grade = [](const raylab::grader::StudentWork& work) { // in a process of its own
        return raylab::grader::StudentRecord{work.name, {{"total", "1"}}};
    };
    const auto graded = [&] { return raylab::grader::readStudentResult(root / "out" / "students" / "alice").has_value(); };
    const auto handler = [] {
        struct sigaction current {};
        ::sigaction(SIGTERM, nullptr, &current);
        return current.sa_handler;
    };
    const auto before = handler();
    {
        const raylab::grader::StopSignals command;
        ::raise(SIGTERM); // caught: only asks the run to stop
        CHECK(raylab::grader::runClass(options, grade) == 128 + SIGTERM);
        CHECK_FALSE(graded());
    }
    CHECK((handler() == before));
    {
        const raylab::grader::StopSignals command;
        CHECK(raylab::grader::runClass(options, grade) == 0);
        CHECK(graded());
        ::raise(SIGTERM); // this process would die here if the run had given the signal back
        CHECK((handler() != before));
    }
    CHECK((handler() == before));
    fs::remove_all(root);
}
#endif

#ifdef __linux__

namespace {

// runClass's exit status, and what it and the students' processes printed.
std::pair<int, std::string> runClassPrinting(const raylab::grader::ClassRunOptions& options,
                                             const raylab::grader::GradeStudent& grade, const fs::path& printed) {
    std::fflush(stdout);
    const int saved = ::dup(1), file = ::open(printed.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    REQUIRE(file >= 0);
    ::dup2(file, 1);
    ::close(file);
    const int status = raylab::grader::runClass(options, grade);
    std::fflush(stdout);
    ::dup2(saved, 1);
    ::close(saved);
    return {status, raylab::test::readFile(printed)};
}

std::size_t occurrences(const std::string& text, const std::string& part) {
    std::size_t count = 0;
    for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++count;
    return count;
}

} // namespace

// A real full disk: the results folder is a tmpfs of 20 MB, and each student's report takes 6 MB.
TEST_CASE("a full results disk: said once, the student concerned not graded, the run stops keeping every result; the "
          "next run, with room, resumes") {
    const fs::path root = raylab::test::freshFolder("raylab-unit-full-disk");
    raylab::test::SmallDisk disk(root / "out", 20);
    if (!disk.mounted()) {
        MESSAGE("SKIPPED: " << disk.why);
        return;
    }
    const std::vector<std::string> names{"ann", "bob", "cid", "dan", "eve", "fay"};
    for (const std::string& name : names) {
        fs::create_directories(root / "class" / name);
        std::ofstream(root / "class" / name / "gradient.cpp") << "// work\n";
    }
    raylab::grader::ClassRunOptions options;
    options.classFolder = root / "class";
    options.out = root / "out";
    const auto grade = [](const raylab::grader::StudentWork& work) {
        raylab::writeFileAtomically(work.folder / "report.bin", std::string(std::size_t(6) << 20, 'r'));
        return raylab::grader::StudentRecord{work.name, {{"total", "1"}}};
    };
    const auto graded = [&] {
        std::vector<std::string> found;
        for (const std::string& name : names)
            if (fs::exists(root / "out" / "students" / name / "result.json")) found.push_back(name);
        return found;
    };
    const std::vector<std::string> firstThree{"ann", "bob", "cid"};

    const auto [status, output] = runClassPrinting(options, grade, root / "first.txt");
    CHECK(status == 1);
    CHECK_MESSAGE(occurrences(output, "not graded: disk full") == 1, output);
    const std::size_t dan = output.find("dan" + std::string(18, ' ') + "not graded: disk full\n"); // its line, padded
    CHECK_MESSAGE((dan == 0 || (dan != std::string::npos && output[dan - 1] == '\n')), output);
    CHECK_MESSAGE(occurrences(output, "stopped: a disk is full") == 1, output);
    CHECK_MESSAGE(output.find("eve") == std::string::npos, output); // the run stopped: no student after
    CHECK(graded() == firstThree);
    CHECK(raylab::test::readCsv(raylab::test::readFile(root / "out" / "grades.csv")).size() == 1 + 3);

    // Still full: the next run keeps the three and stops at the same student, saying so once again.
    const auto [again, againOutput] = runClassPrinting(options, grade, root / "again.txt");
    CHECK(again == 1);
    CHECK_MESSAGE(occurrences(againOutput, "already graded") == 3, againOutput);
    CHECK_MESSAGE(occurrences(againOutput, "not graded: disk full") == 1, againOutput);
    CHECK(graded() == firstThree);

    // With room, the same command resumes where it stopped and ends with every student.
    REQUIRE(disk.resize(100));
    const auto [resumed, resumedOutput] = runClassPrinting(options, grade, root / "resumed.txt");
    CHECK_MESSAGE(resumed == 0, resumedOutput);
    CHECK(occurrences(resumedOutput, "already graded") == 3);
    CHECK(graded() == names);
    CHECK(raylab::test::readCsv(raylab::test::readFile(root / "out" / "grades.csv")).size() == 1 + names.size());
}

// The build's words for a full disk, from a stand-in for CMake: the code's error on a disk with room,
// a full disk (which stops a class run) on one without.
TEST_CASE("a build that fails on a full disk is a full disk, not the code's compile error") {
    const fs::path root = raylab::test::freshFolder("raylab-unit-build-full-disk");
    raylab::test::SmallDisk disk(root / "build", 100);
    if (!disk.mounted()) {
        MESSAGE("SKIPPED: " << disk.why);
        return;
    }
    const fs::path cmake = root / "cmake";
    std::ofstream(cmake) << "#!/bin/sh\necho 'lab3.dir/sphere_geometry.cpp.o: No space left on device' >&2\nexit 1\n";
    fs::permissions(cmake, fs::perms::owner_all);
    fs::create_directories(root / "labs");
    const raylab::grader::Toolchain tools{cmake.string(), "", {}};
    const auto build = [&] { return raylab::grader::buildSubmission(tools, root, root / "labs", root / "build", {}, root / "build.log"); };
    const raylab::grader::SubmissionBuild roomy = build();
    CHECK_MESSAGE(roomy.compilerMessage.find("No space left on device") != std::string::npos, roomy.compilerMessage);

    std::ofstream(root / "build" / "filler", std::ios::binary) << std::string(fs::space(root / "build").available - (1 << 20), 'f');
    try {
        build();
        FAIL("a build on a full disk was graded as the code's error");
    } catch (const std::exception& e) {
        CHECK_MESSAGE(raylab::grader::isDiskFull(e), e.what());
    }
}

#endif

} // TEST_SUITE
#endif
