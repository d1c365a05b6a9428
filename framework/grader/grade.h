#pragma once
// Grading: runs the agents that hold the code (sandbox.h), compares their pictures with the
// references itself (compare.h), names likely mistakes (diagnosis.h) and scores by the labs'
// descriptions (lab_catalog.h). It keeps going whatever the code does: an item the code never reported has
// failed, with the reason.

#include "grader/compare.h"
#include "grader/diagnosis.h"
#include "grader/lab_catalog.h"
#include "grader/references.h"
#include "grader/sandbox.h"

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace raylab::grader {

struct CheckOutcome {
    int lab = 0;
    std::string name;
    bool passed = false;
    std::string message; // expected / got / hint, or why it never ran
    double points = 0., maxPoints = 0.;
};

struct FigureOutcome {
    std::string id;
    int lab = 0;
    bool passed = false;
    bool found = true;   // --images: false when the file is missing (listed, not deciding the exit status)
    std::string reason;  // the verdict's line, or why there is no image
    ImageVerdict verdict;
    std::string diagnosis;              // the closest classic mistake, when one fits
    std::filesystem::path studentImage; // empty when there is none
    double points = 0., maxPoints = 0.;
};

struct LabOutcome {
    int lab = 0;
    double points = 0., maxPoints = 0.;
    std::vector<std::string> notes; // "graded with the other labs from the reference", the labs to fix first
};

struct GradeResult {
    std::string title;
    std::vector<CheckOutcome> checks;
    std::vector<FigureOutcome> figures;
    std::vector<LabOutcome> labs;
    std::vector<std::string> problems; // what went wrong around the items (a crash, a compile error)

    double score() const;
    double maxScore() const;
    bool allPassed() const; // every check and every figure found passed
};

// What every grade needs, loaded once (the references before any student code runs).
struct GradeSetup {
    ReferenceSet references;
    std::vector<Mistake> mistakes;
    LabCatalog labs;               // the labs' descriptions: their items, points and dependencies
    std::filesystem::path scenes;  // the figure scene files, for the agents
    std::filesystem::path scratch; // a folder of our own: agents run and write here
    SandboxLimits limits;
    int threads = 0;
    long long seed = -1; // >= 0: the agents render with this seed instead of the scenes' own
};

// `labs`: the folder of the lab descriptions (labs/<lab>/lab.toml); `scenes`: the figures' scene files.
GradeSetup loadGradeSetup(const std::filesystem::path& references, const std::filesystem::path& labs,
                          const std::filesystem::path& scenes, const std::filesystem::path& scratch);

struct AgentPlan {
    std::filesystem::path program;
    int lab = 0; // 0: every lab, cumulatively; N: lab N only (the other labs built from the reference)
};

// Grades code through its agents. `isolated`: each lab's agent took the other labs from the reference.
// The labs in `unbuilt` had no agent (their code did not compile): zero, with `buildMessage`.
GradeResult gradeCode(const GradeSetup& setup, const std::vector<AgentPlan>& agents, bool isolated,
                      const std::vector<int>& unbuilt = {}, const std::string& buildMessage = "");

// The figures an agent's code renders (those it could), as it sent them; nothing is judged.
std::map<std::string, Image8> renderFigures(const GradeSetup& setup, const std::filesystem::path& agent);

// Grades pictures DIR/<figure id>.png, no code at all.
GradeResult gradeImages(const GradeSetup& setup, const std::filesystem::path& folder);

// A submission that did not build: every item at zero, with the compiler's message.
GradeResult gradeBuildFailure(const GradeSetup& setup, const std::string& compilerMessage);

} // namespace raylab::grader
