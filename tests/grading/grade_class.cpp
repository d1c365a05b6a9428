// raylab grade-class: a row per student, resumable; a submission that does not build gets zero
// for the labs that do not build, with the compiler's message.
#include "grading_support.h"

#include <cstdlib>
#include <fstream>
#include <sstream>

using namespace raylab::test;

namespace {

std::string slurp(const fs::path& file) {
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

int gradeClass(const fs::path& classDir, const fs::path& out, const fs::path& buildDir) {
    std::ostringstream command;
    command << '"' << (binDir() / "raylab").string() << "\" grade-class \"" << classDir.string() << "\" --out \""
            << out.string() << "\" --build-dir \"" << buildDir.string() << "\" > \""
            << (out.parent_path() / "class-output.txt").string() << "\" 2>&1";
    return std::system(command.str().c_str());
}

fs::path makeClass(const std::string& name) {
    const fs::path root = fs::temp_directory_path() / name;
    fs::remove_all(root);
    fs::create_directories(root / "class");
    fs::copy(sourceDir() / "solutions", root / "class" / "alice", fs::copy_options::recursive);
    fs::copy(sourceDir() / "solutions", root / "class" / "bob", fs::copy_options::recursive);
    std::ofstream(root / "class" / "bob" / "lab3_sphere" / "sphere_geometry.cpp", std::ios::app) << "\nnot C++ at all\n";
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
    CHECK(slurp(root / "out" / "grades.csv") == "student,lab1,total\nalice,1,1\nbob,1,1\n");
    CHECK(slurp(root / "class-output.txt").find("bob                  already graded") != std::string::npos);
    CHECK_FALSE(fs::exists(root / "build")); // nothing was built
}

} // TEST_SUITE

TEST_SUITE("class") {

TEST_CASE("grade-class builds and grades each student; a compile error costs only its labs") {
    const fs::path root = makeClass("raylab-class-full");
    const fs::path build = fs::path(RAYLAB_GRADING_BIN).parent_path() / "grading-class-build"; // kept: faster next time
    REQUIRE(gradeClass(root / "class", root / "out", build) == 0);
    const std::string csv = slurp(root / "out" / "grades.csv");
    CHECK_MESSAGE(csv.find("\nalice,10,16,24,12,12,74,74,\n") != std::string::npos, csv);
    CHECK_MESSAGE(csv.find("\nbob,10,16,0,12,12,50,74,") != std::string::npos, csv);
    CHECK(csv.find("sphere_geometry.cpp") != std::string::npos); // the compiler's message
    CHECK(fs::exists(root / "out" / "students" / "bob" / "report" / "index.html"));
    CHECK(fs::exists(root / "out" / "students" / "alice" / "report" / "results.json"));
}

} // TEST_SUITE
