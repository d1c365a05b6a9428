#pragma once
// Helpers of the grader's end-to-end tests: the course's references and labs, and grading an
// agent built by tests/grading/CMakeLists.txt.

#include "grader/judge/grade.h"

#include <doctest/doctest.h>

#include <filesystem>
#include <random>
#include <string>

namespace raylab::test {

namespace fs = std::filesystem;
using namespace raylab::grader;

inline fs::path binDir() { return RAYLAB_GRADING_BIN; }
inline fs::path sourceDir() { return RAYLAB_SOURCE_DIR; }
inline fs::path referencesDir() { return sourceDir() / "framework/grader/data/references"; }

// A setup with a scratch folder of its own (tests run in parallel).
inline GradeSetup courseSetup(const fs::path& references = referencesDir()) {
    std::random_device random;
    GradeSetup setup = loadGradeSetup(references, sourceDir() / "labs", {},
                                      fs::temp_directory_path() / ("raylab-grading-test-" + std::to_string(random())));
    setup.limits.wallSeconds = 60.;
    setup.threads = 2;
    return setup;
}

inline GradeResult gradeAgent(const GradeSetup& setup, const std::string& agent) {
    const fs::path program = binDir() / agent;
    REQUIRE_MESSAGE(fs::exists(program), program.string() << " is not built");
    GradeResult result = gradeCode(setup, {{program, 0}}, false);
    fs::remove_all(setup.scratch);
    return result;
}

inline const CheckOutcome* findCheck(const GradeResult& r, const std::string& name) {
    for (const CheckOutcome& c : r.checks)
        if (c.name == name) return &c;
    return nullptr;
}

inline const FigureOutcome* findFigure(const GradeResult& r, const std::string& id) {
    for (const FigureOutcome& f : r.figures)
        if (f.id == id) return &f;
    return nullptr;
}

inline std::string failures(const GradeResult& r) {
    std::string text;
    for (const CheckOutcome& c : r.checks)
        if (!c.passed) text += "\n  check " + c.name + ": " + c.message;
    for (const FigureOutcome& f : r.figures)
        if (!f.passed) text += "\n  figure " + f.id + ": " + f.reason;
    for (const std::string& p : r.problems) text += "\n  problem: " + p;
    return text;
}

} // namespace raylab::test
