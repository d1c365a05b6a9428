#pragma once
// Room judge/: the checks, the pictures' comparison, diagnoses, verdicts and points; it may include protocol/, sandbox/ and lab_catalog.h.
//
// Grading: runs the agents that hold the code (sandbox.h), compares their pictures with the
// references itself (compare.h), names likely mistakes (diagnosis.h) and scores by the labs'
// descriptions (lab_catalog.h). It keeps going whatever the code does: an item the code never reported has
// failed, with the reason.

#include "grader/judge/diagnosis.h"
#include "grader/judge/outcome.h"
#include "grader/lab_catalog.h"
#include "grader/judge/references.h"
#include "grader/judge/time_budget.h"
#include "grader/sandbox/sandbox.h"

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace raylab::grader {

// What every grade needs, loaded once (the references before any student code runs).
struct GradeSetup {
    ReferenceSet references;
    std::vector<Mistake> mistakes;
    LabCatalog labs;               // the labs' descriptions: their items, points and dependencies
    std::filesystem::path scenes;  // a folder of the figure scene files; empty: the catalogue's (labs/<lab>/scenes/)
    std::filesystem::path scratch; // a folder of our own: agents run and write here
    SandboxLimits limits;
    TimeBudget budget; // each lab's wall-clock time in all (limits.wallSeconds stays each item's)
    int threads = 0;
    long long seed = -1; // >= 0: the agents render with this seed instead of the scenes' own
};

// The scene file of a figure, and the folders an agent reads them from.
std::filesystem::path sceneFile(const GradeSetup& setup, const std::string& figure);
std::vector<std::filesystem::path> sceneFolders(const GradeSetup& setup);

// `references`: the reference folders (each lab's, gradingFolders); `labs`: the folder of the lab
// descriptions (labs/<lab>/lab.toml); `scenes`: a folder of the figures' scene files, or empty for each lab's own.
GradeSetup loadGradeSetup(const std::vector<std::filesystem::path>& references, const std::filesystem::path& labs,
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
