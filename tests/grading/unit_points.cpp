// The points table: the instructor's file, read strictly.
#include "grader/points.h"

#include <doctest/doctest.h>

#include <fstream>

using namespace raylab::grader;
namespace fs = std::filesystem;

namespace {

fs::path writeTable(const std::string& name, const std::string& text) {
    const fs::path file = fs::temp_directory_path() / name;
    std::ofstream(file) << text;
    return file;
}

} // namespace

TEST_SUITE("points table") {

TEST_CASE("points by lab and item, with a fallback") {
    const PointsTable t = loadPointsTable(writeTable("raylab-points-ok.toml", "[lab2]\n\"a check\" = 3\n\"figure x\" = 1.5\n"));
    CHECK(t.points(2, "a check") == 3.);
    CHECK(t.points(2, "figure x") == 1.5);
    CHECK(t.points(2, "unknown", 7.) == 7.);
    CHECK(t.points(4, "a check", 1.) == 1.);
    CHECK(t.has(2, "a check"));
    CHECK_FALSE(t.has(3, "a check"));
}

TEST_CASE("a bad table is refused, naming the file and the problem") {
    CHECK_THROWS_WITH_AS(loadPointsTable(writeTable("raylab-points-bad1.toml", "[lab9]\nx = 1\n")),
                         doctest::Contains("[lab9]"), std::runtime_error);
    CHECK_THROWS_WITH_AS(loadPointsTable(writeTable("raylab-points-bad2.toml", "[lab1]\nx = -1\n")),
                         doctest::Contains("\"x\": points must be a number >= 0"), std::runtime_error);
    CHECK_THROWS_WITH_AS(loadPointsTable(writeTable("raylab-points-bad3.toml", "[lab1\n")),
                         doctest::Contains("raylab-points-bad3.toml:1"), std::runtime_error);
}

TEST_CASE("the course's table names every check of the agent and every figure") {
    const PointsTable t = loadPointsTable(fs::path(RAYLAB_SOURCE_DIR) / "tests/grading/points.toml");
    for (int lab = 1; lab <= 5; ++lab) {
        int checks = 0, figures = 0;
        for (const auto& [item, points] : t.labs.at(lab)) (item.rfind("figure ", 0) == 0 ? figures : checks) += 1;
        CHECK_MESSAGE(checks >= 3, "lab " << lab);
        CHECK_MESSAGE(figures >= 1, "lab " << lab);
    }
    for (const char* figure : {"lab1_gradient", "lab2_directions", "lab3_flat", "lab3_cosine", "lab4_d", "lab5_antialiased"})
        CHECK_MESSAGE(t.has(figure[3] - '0', figureItem(figure)), figure);
}

} // TEST_SUITE
