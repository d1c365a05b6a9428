#pragma once
// Room course/: submissions, class runs, the autograders and the grade reports; it may include every other room.
//
// Building a submission (the grader's copy of its lab files, submission_copy.h) into grading agents,
// with CMake, and finding the agents of a build.

#include "grader/judge/grade.h"
#include "grader/sandbox/process.h"
#include "src/file_lock.h"

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace raylab::grader {

struct Toolchain {
    std::string cmake = "cmake";
    std::string generator; // empty: CMake's default
    std::filesystem::path ccache; // empty: none; else each compiler runs through it
};

struct SubmissionBuild {
    std::vector<AgentPlan> agents; // those that built: one for all labs, or one for each lab
    bool isolated = false;         // each lab's agent has the other labs from the reference (else the
                                   // labs it uses from the submission, the others' stubs)
    std::vector<int> brokenLabs;   // labs whose agent did not build, or was refused (over kAgentProgramBytes)
    std::string compilerMessage;   // buildProblem's, when something did not build
    std::filesystem::path log;
};

// What a build's output says went wrong, for the report: first the causes a person acts on (the
// compiler ran out of memory or time, a file it wrote reached kCompilerFileBytes, the output was cut,
// in the reader's language) in place of the build tools' words for them, then the error lines, each
// once; without any, the output's end.
std::string buildProblem(const KeptOutput& output);

// The agents of a build folder's bin/: one for each of `labs` (those built), with the other labs
// from the reference (`isolated`) when solutions/ was there, else with the labs it uses from the same
// code and the others' stubs; one for all where neither kind is built.
std::vector<AgentPlan> findAgents(const std::filesystem::path& binDir, const std::vector<int>& labs, bool& isolated);
// The CMake target of lab `lab`'s own agent in that build, whichever kind it makes ("raylab-agents",
// all of them, before the first build).
std::string labAgentTarget(const std::filesystem::path& binDir, int lab);
// Those of `labs` whose own agent in `binDir` is missing or older than a file the compiler reads in
// the folder (in `labsDir`) of its lab or, without the reference, of a lab it uses: the last build
// of that code failed, and what runs there is not what the student wrote.
// `tried`: a build of them tried then (a lab newer than its program but older than that is one whose
// code did not compile then, and has not changed since).
std::vector<int> labsNotBuilt(const std::filesystem::path& binDir, const std::filesystem::path& labsDir,
                              const LabCatalog& course, const std::vector<int>& labs,
                              std::filesystem::file_time_type tried = std::filesystem::file_time_type::min());

// A build folder's lock (kBuildLockFile in it): raylab builds there one at a time; a second build
// waits, saying for whom, then finds up to date what the first built.
inline constexpr const char* kBuildLockFile = "raylab-build.lock";
std::unique_ptr<FileLock> lockBuildFolder(const std::filesystem::path& buildDir);

// Configures (once) and builds the agents of the submission's copy `labs` in `buildDir`, keeping
// going past errors so that the labs that compile are still graded: a lab that does not compile costs
// that lab and, without solutions/, the labs that use it (`course`: the labs and their `uses`). The
// build's output, its first and last 64 KB, is written to `log` (empty: buildDir/build.log) when it
// ends. A build that failed on a full disk throws std::filesystem_error (ENOSPC) rather than blame the
// code. A build folder may serve many submissions (a class): each copy's objects are its own (CMake's
// targets are named after the copy's folder).
SubmissionBuild buildSubmission(const Toolchain& tools, const std::filesystem::path& sourceDir,
                                const std::filesystem::path& labs, const std::filesystem::path& buildDir,
                                const LabCatalog& course, const std::filesystem::path& log = {});

// Builds in `buildDir`, once for a class, what every submission links and none changes: the
// framework, the grader, the agents' own code, the reference labs and the stubs (the target
// raylab-grading-kit). buildSubmission in the same folder then compiles a student's lab files and
// links. The output goes to `log`; false when something did not build (each student's build then
// tries again and says why).
bool buildGradingKit(const Toolchain& tools, const std::filesystem::path& sourceDir,
                     const std::filesystem::path& buildDir, const std::filesystem::path& log);

} // namespace raylab::grader
