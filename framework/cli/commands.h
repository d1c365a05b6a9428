#pragma once
// The raylab subcommands. Each file adds its own subcommands to the program's CLI11 app; their
// callbacks set the exit status in the shared context.

#include "grader/judge/grade.h"
#include "src/scene_file.h"

#include <CLI/CLI.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace raylab::grader {
struct LabCatalog;
struct LabDescription;
struct RosterEntry;
}

namespace raylab::cli {

struct Context {
    int argc = 0;
    char** argv = nullptr;
    std::string impl;   // whose lab code: "student" or "reference" (--impl)
    int threads = 0;    // --threads; 0: one per core
    std::string scenes; // --scenes: a folder of figure scene files; empty: each lab's, labs/<lab>/scenes/
    int exitStatus = 0;

    // Adds --threads and --scenes to a subcommand.
    void addRenderOptions(CLI::App* command);
    // Adds --impl to a subcommand.
    void addImplOption(CLI::App* command);
    // True when --impl names the other build: the command has then been run by that program
    // (the student and the reference code define the same functions, so each has its own program).
    bool ranInOtherImpl();
};

// The course's data in the source tree this program was built from: the lab descriptions
// (labs/<lab>/lab.toml) and the grader's references (made by `raylab references`).
std::filesystem::path labsFolder();
// A lab's grading folder, framework/grader/labs/<lab>/, and its references/ in it.
std::filesystem::path gradingFolder(const grader::LabDescription& lab);
std::filesystem::path referencesFolder(const grader::LabDescription& lab);
// The reference folders grading reads: `given` alone (--references) when it is not empty, else each
// course lab's.
std::vector<std::filesystem::path> referenceFolders(const std::string& given);
// The lab descriptions of labsFolder() (the course's), their figures' scene files in each lab's
// scenes/: what says which lab a figure is, whichever folder --scenes names.
grader::LabCatalog courseLabs();
// The figure scene with that role (bench, aliased...): of the --scenes folder when given, else of
// the course's labs (courseLabs); throws SceneError when none has it, or two.
SceneDescription figureWithRole(const std::filesystem::path& scenes, std::string_view role);
// "the labs are 1 2 3 4 5", in the reader's language.
std::string labList(const grader::LabCatalog& labs);

// A program of this build's folder (name.exe on Windows).
std::filesystem::path programInBuild(const std::string& name);
// This program's name in the build: raylab (the student's labs) or raylab-reference.
std::string thisProgram();

// Whether the programs holding the student's labs are as new as the files they are built from (fresh_build.cpp).
enum class FreshBuild {
    Fresh,       // no such file is newer than the programs
    Rebuilt,     // the build brought them up to date
    BuildFailed, // the compiler's errors were shown
    Stale,       // it could not be rebuilt from here; the error names the newer file
};
// What a program is seen to be built from: the lab files this build takes from labs/, or everything
// the grading build compiles (every lab of labs/, framework/ with the labs' grading folders, cmake/).
enum class BuildInputs { StudentLabs, GradingBuild };
// The first file of `inputs` (files, and folders walked through) written after `since`, but for
// handouts and pictures (.md, .png) and hidden files; empty when none is.
std::filesystem::path newerSourceFile(const std::vector<std::filesystem::path>& inputs, std::filesystem::file_time_type since);
// When one of `inputs` is newer than this program (or than the last rebuild of `targets` from here), or
// `missing` (a program it needs is not built yet), builds `targets` first: the first is this program,
// which is then run again in this process's place with the same arguments (the call returns only when
// nothing changed or this program could not be built). The build folder is locked meanwhile
// (grader::lockBuildFolder). In a students' tree, a lab that does not compile is built from its stub
// into this program, so that it still runs (lastBuildProblem says why; grader::labsNotBuilt which).
// GradingBuild: the other targets are the grading programs of `agentLabs`; when only the labs' code
// changed since they were built (from here or by hand), they alone are rebuilt, not this program.
FreshBuild ensureFreshBuild(const Context& context, const std::vector<std::string>& targets, BuildInputs inputs,
                            bool missing = false, const std::vector<int>& agentLabs = {});
// The grading programs brought up to date (ensureFreshBuild): lab `lab`'s alone, or all of them (0).
void ensureFreshAgents(const Context& context, int lab);
// This build's grading programs of `labs`: those whose code the last build compiled, and the labs
// whose code it could not compile (with the compiler's words), which have none: what their program
// would run is older than what the student wrote (grader::labsNotBuilt).
struct BuiltAgents {
    std::vector<grader::AgentPlan> agents;
    bool isolated = false; // each lab's agent has the other labs from the reference
    std::vector<int> unbuilt;
    std::string message;
};
BuiltAgents agentsOfThisBuild(const grader::LabCatalog& course, const std::vector<int>& labs);
// What the compiler said of the code the last build from here could not build ("" when it all built).
std::string lastBuildProblem();
std::filesystem::path lastBuildProblemFile();

// The most render threads raylab starts (--threads): more only exhausts the system.
inline constexpr int kMaxThreads = 1024;

// --threads: 0 (one per core) or 1 to kMaxThreads.
CLI::Validator threadCount();
// A number of seconds: positive and finite (--timeout).
CLI::Validator positiveSeconds();
// An integer in [low, high], shown "low..high" in the help (CLI11's own says "INT in [low - high]"
// after the type, which the help already gives).
CLI::Validator integerIn(std::int64_t low, std::int64_t high);

// A command that times renders (bench, bench-effects): --impl, --threads, --scenes and --repeats
// (renders per measurement, `repeats` unless given); `run(scenes, threads, repeats)` is its exit status.
using TimingRun = int (*)(const std::filesystem::path& scenes, int threads, int repeats);
void addTimingCommand(CLI::App& app, Context& context, const std::string& name, const std::string& description,
                      int repeats, TimingRun run);

// The `study` subcommand, made by whichever study registers first; each study adds its own under it.
CLI::App* studyCommand(CLI::App& app);

void addFigureCommands(CLI::App& app, Context& context); // figures, lab, render, scene-format
void addBenchCommand(CLI::App& app, Context& context);   // bench
void addStudyAntialiasingCommand(CLI::App& app, Context& context); // study antialiasing
void addBenchEffectsCommand(CLI::App& app, Context& context); // bench-effects
void addNumericsCommands(CLI::App& app, Context& context); // numerics, study intersection

} // namespace raylab::cli

namespace raylab::cli {
void addGradeCommands(CLI::App& app, Context& context);      // grade, grade-class
void addReferencesCommand(CLI::App& app, Context& context); // references
void addDistributeCommand(CLI::App& app, Context& context); // distribute
void addAutograderCommand(CLI::App& app, Context& context); // autograder gradescope, github, run
void addClassPageCommand(CLI::App& app, Context& context);  // class-page

// A class run's page, similar submissions and gradebook files in `out` (class_page_command.cpp),
// remade from its results; `roster` names the students' ids (empty: their folders' names).
void remakeClassPage(const std::filesystem::path& out, const std::vector<grader::RosterEntry>& roster);
// --roster's file read, or an error naming it and the problem; nothing when `roster` is empty.
std::vector<grader::RosterEntry> classRoster(const std::string& roster);

// A file of the students' tree: where it goes in the tree, and the file of the source tree it is.
struct TreeFile {
    std::filesystem::path relative;
    std::filesystem::path source;
};

// The files of the students' tree: all but the solutions and what would give them away, and the
// reference of each given lab in framework/given/<lab>/ (its solutions' files and its own header: the
// course leaves it out, and the framework calls its functions). writeStudentTree copies them into
// `out` (new or empty), the students' README over the instructors', and returns how many files it wrote.
std::vector<TreeFile> studentTreeFiles(const std::filesystem::path& source);
int writeStudentTree(const std::filesystem::path& source, const std::filesystem::path& out);

// The students' tree's first command, as its README and `raylab distribute` say it: it installs what
// is missing, builds raylab alone and draws the student's pictures (the grading programs come with
// the first `raylab grade`). The second runs the framework's own test suite, which no student needs.
inline constexpr const char* kStudentsBuildCommand = "scripts/setup.sh && cmake --workflow --preset figures";
inline constexpr const char* kStudentsTestCommand = "scripts/setup.sh --tests && cmake --workflow --preset test";
// The students' README.md (English) and LISEZMOI.md (French) in `tree`: what it holds, how to build
// it, the commands of a lab (students_readme.cpp).
void writeStudentsReadme(const std::filesystem::path& tree, const grader::LabCatalog& labs);
} // namespace raylab::cli

namespace raylab::cli {
void addReportCommand(CLI::App& app, Context& context); // report: the student's lab report kit
void addWatchCommand(CLI::App& app, Context& context);  // watch: the live page (framework/watch/)
} // namespace raylab::cli
