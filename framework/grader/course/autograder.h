#pragma once
// What a course needs to grade where its students hand in: Gradescope (a zip with setup.sh and
// run_autograder, results in /autograder/results/results.json) and GitHub Classroom (a workflow with
// one command-grader step per check or figure). framework/cli/autograder_command.cpp writes them;
// tests/autograder/ runs them.

#include "grader/judge/grade.h"

#include <filesystem>
#include <string>
#include <vector>

namespace raylab::grader {

// --- Submissions as students hand them in -----------------------------------------------------

// Copies the lab files of a submission as students hand it in (lab folders at its top, in labs/, in a
// wrapping folder, named otherwise, or the files flat) into `destination`, emptied first, as
// `<lab id>/<file>`: regular files with the names lab.toml declares, nothing followed
// (submission_copy.h).
void copySubmittedLabs(const std::filesystem::path& submission, const LabCatalog& catalog,
                       const std::filesystem::path& destination);

// --- One item alone (raylab grade --item) -------------------------------------------------------

// The lab of a check (by its name) or a figure (by its id); throws std::invalid_argument otherwise.
int labOfItem(const LabCatalog& catalog, const std::string& item);

// The result restricted to that item: its check or figure, its lab with the item's points, the
// lab's notes and the problems.
GradeResult onlyItem(const GradeResult& result, const std::string& item);

// --- GitHub Classroom ----------------------------------------------------------------------------

struct ClassroomStep {
    std::string id;      // the step's id: letters, digits and '-', unique
    std::string name;    // the check's or the figure's id, as `raylab grade --item` takes it
    std::string title;   // what the workflow shows: the check's title in English, the figure's id
    double points = 0.;
};

// One step per check and figure of every lab, in the labs' order.
std::vector<ClassroomStep> classroomSteps(const LabCatalog& catalog);

// The command a step runs in the students' repository (POSIX shell).
std::string classroomCommand(const ClassroomStep& step);

// .github/workflows/classroom.yml (on push, workflow_dispatch and repository_dispatch): checkout,
// one build step, a command-grader step per item, the HTML report uploaded as an artifact, then the
// grading reporter over every step; every step after the build runs even when the build failed.
// Throws std::invalid_argument when an item's points are not a whole number (the reporter reads
// them with parseInt).
std::string classroomWorkflow(const LabCatalog& catalog);

// The workflow's build: only what grading needs, without link-time optimisation, on every core,
// past the files that do not compile (POSIX shell).
std::string classroomBuildCommand();

// --- Gradescope ----------------------------------------------------------------------------------

// The environment variable that moves Gradescope's /autograder elsewhere (tests), and its default.
inline constexpr const char* kAutograderRootVariable = "RAYLAB_AUTOGRADER_ROOT";
std::filesystem::path autograderRoot();

// The zip's two scripts. The students' tree is the zip's raylab/ folder, so /autograder/source/raylab;
// it carries the reference labs (solutions/) and the header-only libraries (third_party/).
std::string gradescopeSetupScript();
std::string gradescopeRunScript();

struct ZipEntry {
    std::string name;              // its path in the archive
    std::filesystem::path file;    // read from this file, or
    std::string content;           // this text when `file` is empty
    bool executable = false;
};

// Writes the archive whole: into a temporary file beside `zip`, renamed over it at the end.
void writeZip(const std::filesystem::path& zip, const std::vector<ZipEntry>& entries);

} // namespace raylab::grader
