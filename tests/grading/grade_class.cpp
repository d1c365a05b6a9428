// raylab grade-class: a row per student, resumable; a submission that does not build gets zero
// for the labs that do not build, with the compiler's message.
#include "support/files.h"
#include "grading_support.h"
#include "support/run_program.h"

#include <fstream>
#include <string>
#include <vector>

using namespace raylab::test;

namespace {

using raylab::test::readFile;

// Runs grade-class from the class's parent folder (where a command run by mistake would write).
// Without bubblewrap where this system cannot run it (grade-class refuses otherwise).
int gradeClass(const fs::path& classDir, const fs::path& out, const fs::path& buildDir) {
    std::vector<std::string> argv{(binDir() / "raylab").string(), "grade-class", classDir.string(), "--out", out.string(),
                                  "--build-dir", buildDir.string()};
    if (!bubblewrapMissing().empty()) argv.push_back("--no-sandbox");
    return runProgram(argv, out.parent_path() / "class-output.txt", classDir.parent_path()).status;
}

// The rows of a CSV file, quoting read as written (a field may hold a comma, a quote, a newline).
std::vector<std::vector<std::string>> readCsv(const std::string& text) {
    std::vector<std::vector<std::string>> rows(1, std::vector<std::string>(1));
    bool quoted = false;
    for (std::size_t k = 0; k < text.size(); ++k) {
        const char c = text[k];
        if (quoted && c == '"' && k + 1 < text.size() && text[k + 1] == '"') rows.back().back() += text[++k];
        else if (c == '"') quoted = !quoted;
        else if (!quoted && c == ',') rows.back().emplace_back();
        else if (!quoted && c == '\n') rows.emplace_back(1);
        else rows.back().back() += c;
    }
    if (rows.back().size() == 1 && rows.back()[0].empty()) rows.pop_back();
    return rows;
}

fs::path makeClass(const std::string& name) {
    const fs::path root = fs::temp_directory_path() / name;
    fs::remove_all(root);
    fs::create_directories(root / "class");
    fs::copy(sourceDir() / "solutions", root / "class" / "alice", fs::copy_options::recursive);
    fs::copy(sourceDir() / "solutions", root / "class" / "bob", fs::copy_options::recursive);
    std::ofstream(root / "class" / "bob" / "lab3_sphere" / "sphere_geometry.cpp", std::ios::app) << "\nnot C++ at all\n";
    return root;
    // Bob's lab 4 is the reference, included from the grader's tree through the framework's include
    // folder (raylab/../../../ is the tree's root): it must not build.
    std::ofstream(root / "class" / "bob" / "lab4_lookat_camera" / "look_at.cpp")
        << "#if __has_include(\"raylab/../../../solutions/lab4_lookat_camera/look_at.cpp\")\n"
           "#include \"raylab/../../../solutions/lab4_lookat_camera/look_at.cpp\"\n"
           "#endif\n";
    return root;
}

} // namespace

TEST_SUITE("commands") {

TEST_CASE("grade-class resumes: students with a result are not graded again, the CSV is made from the results") {
    const fs::path root = makeClass("raylab-class-resume");
    for (const char* name : {"alice", "bob"}) {
        fs::create_directories(root / "out" / "students" / name);
        std::ofstream(root / "out" / "students" / name / "result.json")
            << R"({"student": ")" << name << R"(", "cells": [{"column": "lab1", "value": "1"}, {"column": "total", "value": "1"}]})";
    }
    CHECK(gradeClass(root / "class", root / "out", root / "build") == 0);
    CHECK(readFile(root / "out" / "grades.csv") == "student,lab1,total\nalice,1,1\nbob,1,1\n");
    CHECK(readFile(root / "class-output.txt").find("bob                  already graded") != std::string::npos);
    CHECK_FALSE(fs::exists(root / "build")); // nothing was built
}

} // TEST_SUITE

TEST_SUITE("class") {

// Grades a class of correct solutions under these folder names: none is run as a command, and
// each gets one row with full points.
void gradeCorrectClass(const std::string& test, const std::vector<std::string>& names) {
    const fs::path root = fs::temp_directory_path() / test;
    fs::remove_all(root);
    fs::create_directories(root / "class");
    for (const std::string& name : names)
        fs::copy(sourceDir() / "solutions", root / "class" / name, fs::copy_options::recursive);
    const fs::path build = fs::path(RAYLAB_GRADING_BIN).parent_path() / "grading-class-build"; // kept: faster next time
    const int status = gradeClass(root / "class", root / "out", build);
    const std::string output = readFile(root / "class-output.txt");
    REQUIRE_MESSAGE(status == 0, output);
    for (const fs::path& folder : {root, root / "class", root / "out"}) CHECK_FALSE(fs::exists(folder / "PWNED"));
    const auto rows = readCsv(readFile(root / "out" / "grades.csv"));
    for (const std::string& name : names) {
        CAPTURE(name);
        int found = 0;
        for (const auto& row : rows)
            if (!row.empty() && row[0] == name) {
                ++found;
                REQUIRE(row.size() == 9);
                CHECK_MESSAGE(row[6] == row[7], "total " << row[6] << " of " << row[7] << ": " << row[8]);
            }
        CHECK(found == 1);
    }
}

TEST_CASE("grade-class: a folder name is never run as a command, and each correct solution gets full points") {
    gradeCorrectClass("raylab-class-hostile-names",
                      {"dollar$(touch PWNED)", "back`touch PWNED`tick", "dollar$HOME", "double\"quote", "single'quote",
                       "with space", "-leading-dash", "semi;colon", "ünicöde 名前", "comma,name", "new\nline"});
}

TEST_CASE("grade-class: students named like its own files (grades.csv, build) are graded like the others") {
    gradeCorrectClass("raylab-class-own-names", {"grades.csv", "build"});
}

TEST_CASE("grade-class builds and grades each student; a compile error costs only its labs") {
    const fs::path root = makeClass("raylab-class-full");
    const fs::path build = fs::path(RAYLAB_GRADING_BIN).parent_path() / "grading-class-build"; // kept: faster next time
    REQUIRE(gradeClass(root / "class", root / "out", build) == 0);
    const std::string csv = readFile(root / "out" / "grades.csv");
    CHECK_MESSAGE(csv.find("\nalice,10,16,24,12,13,75,75,\n") != std::string::npos, csv);
    // Lab 4 read the reference (raylab-build-guard): it does not build either, and the grade says why.
    CHECK_MESSAGE(csv.find("\nbob,10,16,0,0,13,39,75,") != std::string::npos, csv);
    CHECK(csv.find("solutions/lab4_lookat_camera/look_at.cpp, outside your submission") != std::string::npos);
    CHECK(csv.find("sphere_geometry.cpp") != std::string::npos); // the compiler's message
    CHECK(fs::exists(root / "out" / "students" / "bob" / "report" / "index.html"));
    CHECK(fs::exists(root / "out" / "students" / "alice" / "report" / "results.json"));
}

} // TEST_SUITE
