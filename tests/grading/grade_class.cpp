// raylab grade-class: a row per student, resumable; a submission that does not build gets zero
// for the labs that do not build, with the compiler's message.
#include "support/files.h"
#include "grading_support.h"
#include "grader/course/class_run.h"
#include "src/text.h"
#include "grader/sandbox/process.h"
#include "support/read_csv.h"
#include "support/run_program.h"

#include <algorithm>
#include <fstream>
#include <map>
#include <string>
#include <vector>

using namespace raylab::test;

namespace {

// Runs grade-class from the class's parent folder (where a command run by mistake would write).
// Without bubblewrap where this system cannot run it (grade-class refuses otherwise).
// The class builds in out/build unless `buildDir` is given.
int gradeClass(const fs::path& classDir, const fs::path& out, const fs::path& buildDir = {}) {
    std::vector<std::string> argv{(binDir() / "raylab").string(), "grade-class", classDir.string(), "--out", out.string()};
    if (!buildDir.empty()) argv.insert(argv.end(), {"--build-dir", buildDir.string()});
    if (!bubblewrapMissing().empty()) argv.push_back("--no-sandbox");
    return runProgram(argv, out.parent_path() / "class-output.txt", classDir.parent_path()).status;
}

// Bob's two broken labs, the course's last two: the last does not compile, the one before is the
// reference, included from the grader's tree.
const LabDescription& notCompiling() { static const LabDescription lab = loadLabCatalog(sourceDir() / "labs").labs.back(); return lab; }
const LabDescription& includingReference() {
    static const LabDescription lab = [] {
        const LabCatalog course = loadLabCatalog(sourceDir() / "labs");
        REQUIRE(course.labs.size() >= 2);
        return course.labs[course.labs.size() - 2];
    }();
    return lab;
}
// The file of `lab` bob breaks: its first.
std::string firstFile(const LabDescription& lab) { return lab.files().at(0); }

fs::path makeClass(const std::string& name) {
    const fs::path root = raylab::test::scratchPath(name);
    fs::remove_all(root);
    fs::create_directories(root / "class");
    copyCourseSolutions(root / "class" / "alice");
    copyCourseSolutions(root / "class" / "bob");
    std::ofstream(root / "class" / "bob" / notCompiling().id / firstFile(notCompiling()), std::ios::app) << "\nnot C++ at all\n";
    // The reference, through the framework's include folder (raylab/../../../ is the tree's root): it
    // must not build.
    const std::string reference = "raylab/../../../solutions/" + includingReference().id + "/" + firstFile(includingReference());
    std::ofstream(root / "class" / "bob" / includingReference().id / firstFile(includingReference()))
        << "#if __has_include(\"" << reference << "\")\n#include \"" << reference << "\"\n#endif\n";
    return root;
}

} // namespace

TEST_SUITE("commands") {

// The reference folders as a result's settings name them: each lab's, absolute.
std::string referencesShown() {
    std::string shown;
    for (const fs::path& folder : referenceDirs())
        shown += (shown.empty() ? "" : " ") + fs::absolute(folder).lexically_normal().string();
    return shown;
}

TEST_CASE("grade-class resumes: students with a result are not graded again, the CSV is made from the results") {
    const fs::path root = makeClass("raylab-class-resume");
    // Made as this run makes them: every lab, the default timeout, this grader, its sandbox.
    const std::string sandbox = bubblewrapMissing().empty() ? "bubblewrap" : "process group";
    const std::string madeBy = R"([{"name": "grader", "value": "raylab )" RAYLAB_VERSION R"("}, {"name": "labs", "value": "all"},
        {"name": "timeout", "value": "180"}, {"name": "sandbox", "value": ")" + sandbox + R"("},
        {"name": "references", "value": ")" + referencesShown() + R"("},
        {"name": "agents", "value": "built from each submission"}])";
    for (const char* name : {"alice", "bob"}) {
        fs::create_directories(root / "out" / "students" / name);
        std::ofstream(root / "out" / "students" / name / "result.json")
            << R"({"student": ")" << name << R"(", "cells": [{"column": "lab1", "value": "1"}, {"column": "total", "value": "1"}], )"
            << R"("made_by": )" << madeBy << "}";
    }
    CHECK(gradeClass(root / "class", root / "out", root / "build") == 0);
    CHECK(readFile(root / "out" / "grades.csv") == "student,lab1,total\nalice,1,1\nbob,1,1\n");
    CHECK(readFile(root / "class-output.txt").find("bob                  already graded") != std::string::npos);
    CHECK_FALSE(fs::exists(root / "build")); // nothing was built
}

} // TEST_SUITE

TEST_SUITE("class") {

// Names CMake and a shell would misread (each character of the hostile-names list of
// class_ledger.cpp, in two folders: each builds its own tree), and grade-class's own file names.
const std::vector<std::string> kHostileNames{"-dollar$(touch PWNED) back`touch PWNED`tick $HOME",
                                             "double\"single'semi;colon,comma ünicöde 名前\nline", "grades.csv", "build"};

TEST_CASE("grade-class builds the framework once and grades each student in its own folder: hostile names are never "
          "run as commands, each correct solution gets full points, a compile error costs only its labs") {
    const fs::path root = makeClass("raylab-class-full");
    for (const std::string& name : kHostileNames) copyCourseSolutions(root / "class" / name);
    const int status = gradeClass(root / "class", root / "out");
    const std::string output = readFile(root / "class-output.txt");
    REQUIRE_MESSAGE(status == 0, output);
    for (const fs::path& folder : {root, root / "class", root / "out"}) CHECK_FALSE(fs::exists(folder / "PWNED"));

    const auto rows = readCsv(readFile(root / "out" / "grades.csv"));
    REQUIRE(rows.size() == 1 + 2 + kHostileNames.size()); // the header, alice, bob, the hostile names
    CHECK(rows[0] == expectedCsvHeader());
    const std::size_t total = rows[0].size() - 3, max = total + 1, problems = total + 2;
    for (const std::string& name : kHostileNames) {
        CAPTURE(name);
        std::string shown = raylab::printableName(name); // one line in grades.csv, a formula defused
        if (std::string("=+-@").find(shown[0]) != std::string::npos) shown = "'" + shown;
        CHECK(std::count_if(rows.begin(), rows.end(), [&](const auto& row) { return row[0] == shown; }) == 1);
    }
    for (const auto& row : rows) {
        CAPTURE(row[0]);
        REQUIRE(row.size() == rows[0].size());
        if (row[0] == "student") continue;
        if (row[0] == "bob") {
            // A compile error in one lab, the reference read in the other: neither builds, and the problems
            // say why. Under bubblewrap the compiler does not see the reference (the lab is empty and does
            // not link); without it, raylab-build-guard refuses what the compiler read.
            CHECK(std::vector<std::string>(row.begin() + 1, row.end() - 1) ==
                  expectedPointsCells({notCompiling().number, includingReference().number}));
            if (bubblewrapMissing().empty())
                CHECK_MESSAGE(row[problems].find("outside your submission") == std::string::npos, row[problems]);
            else
                CHECK(row[problems].find("solutions/" + includingReference().id + "/" + firstFile(includingReference()) +
                                         ", outside your submission") != std::string::npos);
            CHECK(row[problems].find(firstFile(notCompiling())) != std::string::npos); // the compiler's message
        } else {
            CHECK_MESSAGE(row[total] == row[max], "total " << row[total] << " of " << row[max] << ": " << row[problems]);
            CHECK(row[problems].empty());
        }
    }
    // One build folder for the class, through ccache when it is installed (with paths relative to the
    // folder the sources and builds share); the framework compiled there once, before the first
    // student: no student's build compiles a framework file, each compiles its own lab files.
    const std::string cache = readFile(root / "out" / "build" / "CMakeCache.txt");
    CHECK((cache.find("CCACHE_BASEDIR=/") != std::string::npos) == !raylab::grader::findProgram("ccache").empty());
    const std::string kitLog = readFile(root / "out" / "build" / "grading-kit.log");
    CHECK(kitLog.find("raylab_framework.dir/src/renderer.cpp") != std::string::npos);
    for (const char* name : {"alice", "bob"}) {
        CAPTURE(name);
        const std::string log = readFile(root / "out" / "students" / name / "build.log");
        CHECK(log.find("raylab_framework.dir") == std::string::npos);
        CHECK(log.find("raylab_grader.dir") == std::string::npos);
        CHECK(log.find(firstFile(includingReference())) != std::string::npos);
        CHECK_FALSE(fs::exists(root / "out" / "students" / name / "build"));
    }
    CHECK(output.find("once for the class") == output.rfind("once for the class")); // built once
    CHECK(fs::exists(root / "out" / "students" / "bob" / "report" / "index.html"));
    CHECK(fs::exists(root / "out" / "students" / "alice" / "report" / "results.json"));
}

TEST_CASE("grade-class takes uploads as students make them: the files flat, odd extra names, a labs/ link to "
          "solutions/ earns 0 and says why, a lab that does not compile costs that lab only") {
    const fs::path root = raylab::test::scratchPath("raylab-class-uploads");
    fs::remove_all(root);
    const fs::path flat = root / "class" / "flat", odd = root / "class" / "odd", linked = root / "class" / "linked",
                   broken = root / "class" / "broken";
    fs::create_directories(flat);
    copyCourseSolutions(root / "course");
    for (const auto& entry : fs::recursive_directory_iterator(root / "course"))
        if (entry.is_regular_file()) fs::copy_file(entry.path(), flat / entry.path().filename());
    fs::create_directories(flat / "__MACOSX");
    std::ofstream(flat / "__MACOSX" / ("._" + firstFile(notCompiling()))) << "resource fork";
    fs::copy(root / "course", odd, fs::copy_options::recursive);
    for (const char* name : {"x;y.cpp", "${HOME}x.cpp", "it's a \"file\".cpp"})
        std::ofstream(odd / notCompiling().id / name) << "not C++\n";
    fs::create_directories(linked);
    fs::create_directory_symlink(sourceDir() / "solutions", linked / "labs");
    fs::copy(root / "course", broken, fs::copy_options::recursive);
    std::ofstream(broken / includingReference().id / firstFile(includingReference()), std::ios::app) << "\nint missing_semicolon = 1\n";

    const int status = gradeClass(root / "class", root / "out");
    REQUIRE_MESSAGE(status == 0, readFile(root / "class-output.txt"));
    const auto rows = readCsv(readFile(root / "out" / "grades.csv"));
    REQUIRE(rows.size() == 5);
    std::map<std::string, std::vector<std::string>> row;
    for (const auto& r : rows) row[r[0]] = r;
    const auto points = [&](const std::string& name) { return std::vector<std::string>(row[name].begin() + 1, row[name].end() - 1); };
    const auto problems = [&](const std::string& name) { return row[name].back(); };
    CHECK(points("flat") == expectedPointsCells());
    CHECK(problems("flat").empty());
    CHECK(points("odd") == expectedPointsCells());
    CHECK(problems("odd").find("left out of the grade (3; the lab files are") != std::string::npos);
    CHECK(points("linked") == expectedPointsCells(everyLab()));
    CHECK(problems("linked").find("no lab file found") != std::string::npos);
    CHECK(problems("linked").find("labs: a symbolic link, not followed") != std::string::npos);
    CHECK(points("broken") == expectedPointsCells({includingReference().number}));
}

} // TEST_SUITE
