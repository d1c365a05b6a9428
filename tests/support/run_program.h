#pragma once
// Tests run the raylab tool and agents as a user would, with an argument vector (never a shell,
// so a path with spaces or quotes is one argument).

#include "grader/sandbox/process.h"
#include "support/files.h"

#include <filesystem>
#include <string>
#include <vector>

namespace raylab::test {

struct ProgramRun {
    int status = -1;    // the exit status; 128 + the signal when one ended it; -1 when it did not start
    std::string output; // its stdout and stderr, together
};

// Runs argv in `cwd` (ours when empty), its output collected in `outputFile` (replaced).
inline ProgramRun runProgram(const std::vector<std::string>& argv, const std::filesystem::path& outputFile,
                             const std::filesystem::path& cwd = {}) {
    std::error_code ignored;
    std::filesystem::remove(outputFile, ignored);
    const grader::ProcessResult result = grader::runProcess(argv, {cwd, outputFile});
    ProgramRun run;
    if (result.started) run.status = result.signal ? 128 + result.signal : result.exitCode;
    run.output = result.started ? readFile(outputFile) : result.error;
    return run;
}

} // namespace raylab::test
