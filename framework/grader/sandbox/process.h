#pragma once
// Starting a program with an argument vector, never through a shell: a folder or file name that
// holds $( ), quotes, spaces or a newline reaches the program as one argument, and nothing in it
// is executed.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace raylab::grader {

// Where output nobody reads goes.
#ifdef _WIN32
inline const char* const kNullDevice = "NUL";
#else
inline const char* const kNullDevice = "/dev/null";
#endif

struct ProcessOptions {
    std::filesystem::path workingDirectory = {}; // empty: ours
    std::filesystem::path output = {};           // stdout and stderr are appended here; empty: ours
    double timeLimit = 0.;                       // seconds; past it the program is killed (0: none)
    std::vector<std::string> environment = {};   // NAME=value, added to ours (POSIX; Windows: ours only)
    // > 0: stdout and stderr are read through a pipe instead, and only their first and last
    // `keepOutput` bytes kept (ProcessResult::kept; `output` unused): a build's output is the
    // submission's to make as long as it likes (a template error of a gigabyte), so it is streamed
    // through, never held in memory nor written to a disk whole.
    std::size_t keepOutput = 0;
    // With keepOutput: what is read is also written to our stdout as it comes (a build's progress).
    bool echo = false;
};

// A program's output as ProcessOptions::keepOutput keeps it.
struct KeptOutput {
    std::string head, tail;  // the first and the last bytes
    std::uint64_t cut = 0;   // how many bytes between them were left out
};

struct ProcessResult {
    bool started = false; // false: the program could not be run (not found, not executable)
    int exitCode = -1;    // when it exited
    int signal = 0;       // when a signal ended it (POSIX)
    std::string error;    // why it could not be started
    KeptOutput kept;      // with ProcessOptions::keepOutput
    bool succeeded() const { return started && signal == 0 && exitCode == 0; }
};

// Runs argv[0] (searched in PATH when it names no folder) with argv[1...], stdin from the null
// device, and waits for it.
ProcessResult runProcess(const std::vector<std::string>& argv, const ProcessOptions& options = {});

// The program `name` as the PATH search finds it (`name.exe` on Windows); empty when it is not there.
std::filesystem::path findProgram(const std::string& name);

#ifdef _WIN32
// `argv` as one Windows command line that CommandLineToArgvW splits back into `argv` (no shell).
std::wstring windowsCommandLine(const std::vector<std::string>& argv);
#endif

// `args` as exec and spawn take them: a pointer to each argument's characters, then a null pointer
// (valid while `args` lives unchanged).
std::vector<char*> argumentPointers(std::vector<std::string>& args);

// Whether runProcess (in any thread) is waiting for process `pid`: the sandbox's sweep kills the
// processes an agent left behind, never these. Safe in a signal handler.
bool isRunningProcess(long pid);

} // namespace raylab::grader
