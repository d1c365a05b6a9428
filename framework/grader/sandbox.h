#pragma once
// Runs a grading agent (untrusted: it holds the student's code) and collects what it reports.
// POSIX: a child process in its own process group and scratch folder, with setrlimit limits on
// CPU time, memory and file size, a wall-clock timeout, and results read from a pipe the parent
// opened (the child's stdout goes to a capped file nobody trusts). Elsewhere: std::system with a
// result file, without limits (the student's own machine, grading the student's own code).

#include <filesystem>
#include <string>
#include <vector>

namespace raylab::grader {

struct SandboxLimits {
    int cpuSeconds = 600;       // CPU time of the whole run
    double wallSeconds = 180.;  // wall-clock time without a word from the child: each check and figure
                                // announces itself, so this is a limit per item, and a slow item
                                // never makes the next one late
    double totalSeconds = 1800.; // wall-clock time of the whole run
    unsigned long long memoryBytes = 4ull << 30;
    unsigned long long fileBytes = 256ull << 20;
};

struct AgentRun {
    std::vector<std::string> lines; // what the agent reported, one JSON object a line
    bool timedOut = false;
    int exitCode = -1; // when it exited
    int signal = 0;    // when a signal ended it
    std::string stderrTail; // the end of its error output, for the report
    std::string describe() const; // "killed after 180 s", "exited with status 3", "crashed (signal 11)"
};

// Runs `program args... <channel options>` in `scratch` (created), `requests` waiting on its request
// channel. The channel options are "--request-fd N --report-fd N" on POSIX (two pipes the parent
// opened) and "--request-file FILE --report-file FILE" elsewhere.
AgentRun runAgent(const std::filesystem::path& program, const std::vector<std::string>& args,
                  const std::filesystem::path& scratch, const SandboxLimits& limits, const std::string& requests = "");

} // namespace raylab::grader
