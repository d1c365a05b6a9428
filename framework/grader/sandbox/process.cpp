#include "grader/sandbox/process.h"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string_view>

#ifdef _WIN32
#include <windows.h>
#else
#include <csignal>
#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <thread>
#include <sys/wait.h>
#include <unistd.h>
extern char** environ;
#endif

namespace raylab::grader {

namespace {

// Lock-free, so that a signal handler can read it.
std::atomic<long> g_running[64];

struct RunningProcess {
    explicit RunningProcess(long pid) {
        for (std::atomic<long>& slot : g_running) {
            long empty = 0;
            if (slot.compare_exchange_strong(empty, pid)) {
                m_slot = &slot;
                return;
            }
        }
    }
    ~RunningProcess() {
        if (m_slot) m_slot->store(0);
    }
    RunningProcess(const RunningProcess&) = delete;
    RunningProcess& operator=(const RunningProcess&) = delete;
    std::atomic<long>* m_slot = nullptr;
};

// The first and the last `each` bytes of a stream, and how many were left out between them; never
// more than 3 x `each` bytes held, whatever the stream's length.
class OutputKeeper {
public:
    OutputKeeper(std::size_t each, bool echo) : m_each(each), m_echo(echo) {}
    void add(std::string_view bytes) {
        if (m_echo) {
            std::fwrite(bytes.data(), 1, bytes.size(), stdout);
            std::fflush(stdout);
        }
        const std::size_t toHead = std::min(bytes.size(), m_each - m_kept.head.size());
        m_kept.head.append(bytes.substr(0, toHead));
        bytes.remove_prefix(toHead);
        m_kept.tail.append(bytes);
        if (m_kept.tail.size() > 2 * m_each) dropOldest();
    }
    KeptOutput kept() {
        dropOldest();
        return m_kept;
    }

private:
    void dropOldest() {
        if (m_kept.tail.size() <= m_each) return;
        const std::size_t dropped = m_kept.tail.size() - m_each;
        m_kept.tail.erase(0, dropped);
        m_kept.cut += dropped;
    }
    std::size_t m_each;
    bool m_echo;
    KeptOutput m_kept;
};

// Reads are this large: a build that writes fast fills few of them.
constexpr std::size_t kReadBytes = 1 << 16;
// What is read at once, at most: after the program exited, the rest of the pipe's buffer, not the
// output of a process it left writing forever.
constexpr std::size_t kDrainBytes = std::size_t(16) << 20;

} // namespace

std::filesystem::path findProgram(const std::string& name) {
#ifdef _WIN32
    const char separator = ';', *const fallback = "";
    const std::string file = name + ".exe";
#else
    const char separator = ':', *const fallback = "/usr/bin:/bin"; // execvp's search without PATH
    const std::string& file = name;
#endif
    const char* path = std::getenv("PATH");
    std::istringstream folders(path ? path : fallback);
    for (std::string folder; std::getline(folders, folder, separator);) {
        std::error_code error;
        const std::filesystem::path candidate = std::filesystem::path(folder) / file;
        if (folder.empty() || !std::filesystem::is_regular_file(candidate, error)) continue;
#ifndef _WIN32
        if (access(candidate.c_str(), X_OK) != 0) continue;
#endif
        return candidate;
    }
    return {};
}

std::vector<char*> argumentPointers(std::vector<std::string>& args) {
    std::vector<char*> pointers;
    for (std::string& a : args) pointers.push_back(a.data());
    pointers.push_back(nullptr);
    return pointers;
}

bool isRunningProcess(long pid) {
    for (const std::atomic<long>& slot : g_running)
        if (pid != 0 && slot.load() == pid) return true;
    return false;
}

#ifdef _WIN32

namespace {

// One argument as CommandLineToArgvW reads it back: quoted, with the backslashes before a quote
// doubled (the only quoting Windows programs share; no shell is involved).
std::wstring quoteArgument(const std::wstring& arg) {
    if (!arg.empty() && arg.find_first_of(L" \t\n\v\"") == std::wstring::npos) return arg;
    std::wstring quoted = L"\"";
    std::size_t backslashes = 0;
    for (wchar_t c : arg) {
        if (c == L'\\') {
            ++backslashes;
            continue;
        }
        quoted.append(c == L'"' ? 2 * backslashes + 1 : backslashes, L'\\');
        backslashes = 0;
        quoted += c;
    }
    quoted.append(2 * backslashes, L'\\');
    return quoted + L"\"";
}

} // namespace

std::wstring windowsCommandLine(const std::vector<std::string>& argv) {
    std::wstring commandLine;
    for (const std::string& a : argv)
        commandLine += (commandLine.empty() ? L"" : L" ") + quoteArgument(std::filesystem::path(a).wstring());
    return commandLine;
}

namespace {

// What the pipe holds now, into `keeper`, up to `most` bytes; never waits.
void readAvailable(HANDLE pipe, OutputKeeper& keeper, std::size_t most) {
    std::string buffer(kReadBytes, '\0');
    DWORD available = 0;
    while (most > 0 && PeekNamedPipe(pipe, nullptr, 0, nullptr, &available, nullptr) && available > 0) {
        DWORD n = 0;
        const DWORD want = DWORD(std::min<std::size_t>({available, buffer.size(), most}));
        if (!ReadFile(pipe, buffer.data(), want, &n, nullptr) || n == 0) return;
        keeper.add(std::string_view(buffer.data(), n));
        most -= std::min<std::size_t>(most, n);
    }
}

} // namespace

ProcessResult runProcess(const std::vector<std::string>& argv, const ProcessOptions& options) {
    ProcessResult result;
    if (argv.empty()) return result;
    std::wstring commandLine = windowsCommandLine(argv);
    SECURITY_ATTRIBUTES inherit{sizeof(SECURITY_ATTRIBUTES), nullptr, TRUE};
    HANDLE out = INVALID_HANDLE_VALUE, kept = INVALID_HANDLE_VALUE;
    STARTUPINFOW startup{};
    startup.cb = sizeof startup;
    if (options.keepOutput > 0) {
        if (!CreatePipe(&kept, &out, &inherit, 0)) {
            result.error = "cannot make a pipe (error " + std::to_string(GetLastError()) + ")";
            return result;
        }
        SetHandleInformation(kept, HANDLE_FLAG_INHERIT, 0); // our end only
    } else if (!options.output.empty()) {
        out = CreateFileW(options.output.wstring().c_str(), FILE_APPEND_DATA, FILE_SHARE_READ | FILE_SHARE_WRITE, &inherit,
                          OPEN_ALWAYS, FILE_ATTRIBUTE_NORMAL, nullptr);
        if (out == INVALID_HANDLE_VALUE) {
            result.error = "cannot open " + options.output.string();
            return result;
        }
    }
    if (out != INVALID_HANDLE_VALUE) {
        startup.dwFlags = STARTF_USESTDHANDLES;
        startup.hStdInput = GetStdHandle(STD_INPUT_HANDLE);
        startup.hStdOutput = out;
        startup.hStdError = out;
    }
    PROCESS_INFORMATION process{};
    const std::wstring folder = options.workingDirectory.wstring();
    const BOOL ok = CreateProcessW(nullptr, commandLine.data(), nullptr, nullptr, TRUE, 0, nullptr,
                                   folder.empty() ? nullptr : folder.c_str(), &startup, &process);
    const DWORD startError = GetLastError();
    if (out != INVALID_HANDLE_VALUE) CloseHandle(out);
    if (!ok) {
        if (kept != INVALID_HANDLE_VALUE) CloseHandle(kept);
        result.error = "cannot run " + argv[0] + " (error " + std::to_string(startError) + ")";
        return result;
    }
    OutputKeeper keeper(options.keepOutput, options.echo);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(options.timeLimit);
    // Without a pipe to read, one wait; with one, short waits between its reads.
    const DWORD step = kept != INVALID_HANDLE_VALUE ? 50
                       : options.timeLimit > 0.      ? DWORD(options.timeLimit * 1000.)
                                                     : INFINITE;
    for (;;) {
        if (kept != INVALID_HANDLE_VALUE) readAvailable(kept, keeper, kDrainBytes);
        if (WaitForSingleObject(process.hProcess, step) != WAIT_TIMEOUT) break;
        if (options.timeLimit > 0. && (kept == INVALID_HANDLE_VALUE || std::chrono::steady_clock::now() > deadline)) {
            TerminateProcess(process.hProcess, 1);
            WaitForSingleObject(process.hProcess, INFINITE);
            break;
        }
    }
    if (kept != INVALID_HANDLE_VALUE) {
        readAvailable(kept, keeper, kDrainBytes);
        CloseHandle(kept);
        result.kept = keeper.kept();
    }
    DWORD code = 0;
    GetExitCodeProcess(process.hProcess, &code);
    CloseHandle(process.hThread);
    CloseHandle(process.hProcess);
    result.started = true;
    result.exitCode = int(code);
    return result;
}

#else

namespace {

// Reads the pipe `output` into `keeper` for up to 50 ms, or (`drain`) whatever it holds now, up to
// kDrainBytes. False once it is closed (every writer gone), or drained.
bool readOutput(int output, OutputKeeper& keeper, bool drain) {
    std::string buffer(kReadBytes, '\0');
    for (std::size_t drained = 0; !drain || drained < kDrainBytes;) {
        pollfd ready{output, POLLIN, 0};
        const int polled = poll(&ready, 1, drain ? 0 : 50);
        if (polled < 0 && errno == EINTR) continue;
        if (polled <= 0) return !drain;
        const ssize_t n = read(output, buffer.data(), buffer.size());
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        keeper.add(std::string_view(buffer.data(), std::size_t(n)));
        if (!drain) return true;
        drained += std::size_t(n);
    }
    return false;
}

// Waits for `pid` into `status`, killing it once `timeLimit` seconds (> 0) have passed: a program
// that hangs is stopped, not waited for. Meanwhile its output pipe `output` (-1: none) is read into
// `keeper`, so that the program never waits on a full pipe. Returns 0, or the errno of a wait that
// failed.
int waitFor(pid_t pid, double timeLimit, int& status, int output, OutputKeeper& keeper) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeLimit);
    bool reading = output >= 0;
    for (;;) {
        const pid_t done = waitpid(pid, &status, timeLimit > 0. || reading ? WNOHANG : 0);
        if (done == pid) {
            if (reading) readOutput(output, keeper, true);
            return 0;
        }
        if (done < 0 && errno != EINTR) return errno;
        if (done == 0) {
            if (timeLimit > 0. && std::chrono::steady_clock::now() > deadline) kill(pid, SIGKILL);
            if (reading) reading = readOutput(output, keeper, false);
            else std::this_thread::sleep_for(std::chrono::milliseconds(50));
        }
    }
}

} // namespace

ProcessResult runProcess(const std::vector<std::string>& argv, const ProcessOptions& options) {
    ProcessResult result;
    if (argv.empty()) return result;
    std::vector<std::string> args = argv;
    const std::vector<char*> cargs = argumentPointers(args);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    int stream[2] = {-1, -1}; // with keepOutput: the program writes into [1], we read [0]
    if (options.keepOutput > 0) {
        if (pipe2(stream, O_CLOEXEC) != 0) {
            posix_spawn_file_actions_destroy(&actions);
            result.error = std::string("cannot make a pipe: ") + std::strerror(errno);
            return result;
        }
        posix_spawn_file_actions_adddup2(&actions, stream[1], 1); // dup2 clears O_CLOEXEC on 1 and 2
        posix_spawn_file_actions_adddup2(&actions, stream[1], 2);
    } else if (!options.output.empty()) {
        posix_spawn_file_actions_addopen(&actions, 1, options.output.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
        posix_spawn_file_actions_adddup2(&actions, 1, 2);
    }
    if (!options.workingDirectory.empty())
        posix_spawn_file_actions_addchdir_np(&actions, options.workingDirectory.c_str());
    std::vector<std::string> variables = options.environment;
    for (char** v = environ; *v; ++v) variables.emplace_back(*v); // ours after: the options' come first
    const std::vector<char*> cvariables = argumentPointers(variables);
    pid_t pid = -1;
    const int error = posix_spawnp(&pid, cargs[0], &actions, nullptr, cargs.data(), cvariables.data());
    posix_spawn_file_actions_destroy(&actions);
    if (stream[1] >= 0) close(stream[1]); // the program's end: its last writer closing it ends the stream
    if (error != 0) {
        if (stream[0] >= 0) close(stream[0]);
        result.error = "cannot run " + argv[0] + ": " + std::strerror(error);
        return result;
    }
    const RunningProcess running(pid);
    int status = 0;
    OutputKeeper keeper(options.keepOutput, options.echo);
    const int lost = waitFor(pid, options.timeLimit, status, stream[0], keeper);
    if (stream[0] >= 0) close(stream[0]); // a process the program left writing gets SIGPIPE
    result.kept = keeper.kept();
    if (lost != 0) {
        result.error = "lost " + argv[0] + ": " + std::strerror(lost);
        return result;
    }
    result.started = true;
    if (WIFEXITED(status)) result.exitCode = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) result.signal = WTERMSIG(status);
    return result;
}

#endif

} // namespace raylab::grader
