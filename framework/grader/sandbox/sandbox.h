#pragma once
// Room sandbox/: runs a program confined and reads back what it said; it includes nothing of the grader's other rooms.
//
// Runs a grading agent (untrusted: it holds the student's code) and collects what it reports.
//
// Linux with bubblewrap (`bwrap` in PATH): the agent runs in its own mount, PID and network
// namespaces: it sees the system's libraries read-only, the program and the files it is given
// read-only, a private /tmp, and writes only to its scratch folder (and the folders it is given);
// it cannot see or signal any process outside, has no network, and dies with the grader.
// Linux without bubblewrap (not installed, or a container that forbids namespaces), the grader
// being root: the fallback (unprivileged.h), the agent as an unprivileged user in a scratch folder
// only it can write, under a seccomp filter (no network, no ptrace), with what follows.
// POSIX without either: its own session and process group, the grader ignores (and records)
// signals from it, and every process it started is killed when it ends. All: rlimits on CPU,
// memory and file size, a wall-clock limit per item, and results read from a pipe the parent
// opened (its stdout goes to a capped file nobody trusts; what the parent reads back from its scratch
// folder is read without following links, see scratch_file.h).
// Windows: no bubblewrap, so no confinement of files or network (the grade says so, as with
// --no-sandbox), but a Job object with the same limits: per item and in all, CPU time, memory and
// output size, its whole tree killed at the end (job_object.h); results read from a file.

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace raylab::grader {

struct SandboxLimits {
    int cpuSeconds = 600;       // CPU time of the whole run
    double wallSeconds = 180.;  // wall-clock time without a word from the child: each check and figure
                                // announces itself, so this is a limit per item, and a slow item
                                // never makes the next one late
    double totalSeconds = 1800.; // wall-clock time of the whole run, stopped or asleep included (a
                                 // session gives each run what is left of its lab's budget)
    unsigned long long memoryBytes = 4ull << 30; // all of its processes together where the machine
                                                 // gives the grader a cgroup, else each process
    unsigned long long fileBytes = 256ull << 20; // each file it writes
    unsigned long long diskBytes = 256ull << 20; // everything in its scratch folder, its /tmp included
    int processes = 256; // at once, threads and its own included: a cgroup's pids limit, else RLIMIT_NPROC of
                         // the fallback's user
    bool bubblewrap = true; // use it, or the fallback, when they can run (false: `--no-sandbox`; the
                            // environment's RAYLAB_SANDBOX=bubblewrap|fallback|none chooses too)
};

// What a run keeps of its stdout.txt and stderr.txt, on disk too (their last bytes): the file size
// limit bounds them while it runs, this once it has ended.
constexpr std::size_t kOutputKeptBytes = 64u << 10;

struct AgentCommand {
    std::filesystem::path program;
    std::vector<std::string> args;
    std::filesystem::path scratch;               // created; the agent's working folder, writable
    std::vector<std::filesystem::path> readable = {}; // files and folders it may read (scenes, inputs)
    std::vector<std::filesystem::path> writable = {}; // folders it may write besides its scratch (created)
    std::string requests = {}; // what it reads on its request pipe ("--request-fd 4"), then end-of-file
};

struct AgentRun {
    std::vector<std::string> lines; // what the agent reported, one JSON object a line
    bool timedOut = false;
    int exitCode = -1; // when it exited
    int signal = 0;    // when a signal ended it
    bool cpuLimit = false;    // Windows: the job used up its CPU time (POSIX: SIGXCPU)
    bool outputLimit = false; // Windows: it wrote more than SandboxLimits::fileBytes (POSIX: SIGXFSZ)
    bool diskLimit = false;     // its scratch folder grew past SandboxLimits::diskBytes: killed
    bool processLimit = false;  // it tried more than SandboxLimits::processes at once
    bool memoryLimit = false;   // its processes together used SandboxLimits::memoryBytes (a cgroup's)
    SandboxLimits limits = {};  // what it ran under, for describe()
    std::vector<std::string> violations; // what it tried against the grader ("sent signal 15 to the grader",
                                         // "replaced its output file stderr.txt with a link or a special file")
    std::string stderrTail; // the end of its error output, for the report
    // "stopped: it ran past the time limit", "wrote more than 256 MB", "exited with status 3", "crashed (signal 11)"
    std::string describe() const;
};

// Runs `program args... --request-fd 4 --report-fd 3` (POSIX: two pipes the parent opened; the
// requests are written as the child reads them, so the parent never blocks on a child that stops
// reading) or `... --request-file F --report-file F` (Windows) in `command.scratch`, confined as
// described above.
AgentRun runAgent(const AgentCommand& command, const SandboxLimits& limits);

// How agents are confined with these limits: "bubblewrap", "unprivileged user" (the fallback; with
// ", no seccomp filter" when built without libseccomp), "process group", or "job object" (Windows).
std::string sandboxKind(const SandboxLimits& limits);

// Why bubblewrap cannot confine agents here, in the reader's language ("bubblewrap is not installed
// (no bwrap in PATH)"); empty when it can. Looked up once: `bwrap` in PATH, able to make its namespaces.
std::string bubblewrapMissing();

} // namespace raylab::grader
