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

TEST_CASE("grade-class resumes: students already in the CSV are not graded again") {
    const fs::path root = makeClass("raylab-class-resume");
    fs::create_directories(root / "out");
    const std::string csv = "student,lab1,lab2,lab3,lab4,lab5,total,max,problems\nalice,1,2,3,4,5,15,74,\nbob,0,0,0,0,0,0,74,\n";
    std::ofstream(root / "out" / "grades.csv") << csv;
    CHECK(gradeClass(root / "class", root / "out", root / "build") == 0);
    CHECK(slurp(root / "out" / "grades.csv") == csv);
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
    CHECK_MESSAGE(csv.find("\nalice,10,16,24,12,13,75,75,\n") != std::string::npos, csv);
    CHECK_MESSAGE(csv.find("\nbob,10,16,0,12,13,51,75,") != std::string::npos, csv);
    CHECK(csv.find("sphere_geometry.cpp") != std::string::npos); // the compiler's message
    CHECK(fs::exists(root / "out" / "bob" / "index.html"));
    CHECK(fs::exists(root / "out" / "alice" / "results.json"));
}

} // TEST_SUITE
