#include "grader/sandbox/process.h"

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <sstream>

#ifdef _WIN32
#include <windows.h>
#else
#include <csignal>
#include <fcntl.h>
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

ProcessResult runProcess(const std::vector<std::string>& argv, const ProcessOptions& options) {
    ProcessResult result;
    if (argv.empty()) return result;
    std::wstring commandLine = windowsCommandLine(argv);
    SECURITY_ATTRIBUTES inherit{sizeof(SECURITY_ATTRIBUTES), nullptr, TRUE};
    HANDLE out = INVALID_HANDLE_VALUE;
    STARTUPINFOW startup{};
    startup.cb = sizeof startup;
    if (!options.output.empty()) {
        out = CreateFileW(options.output.wstring().c_str(), FILE_APPEND_DATA, FILE_SHARE_READ | FILE_SHARE_WRITE, &inherit,
                          OPEN_ALWAYS, FILE_ATTRIBUTE_NORMAL, nullptr);
        if (out == INVALID_HANDLE_VALUE) {
            result.error = "cannot open " + options.output.string();
            return result;
        }
        startup.dwFlags = STARTF_USESTDHANDLES;
        startup.hStdInput = GetStdHandle(STD_INPUT_HANDLE);
        startup.hStdOutput = out;
        startup.hStdError = out;
    }
    PROCESS_INFORMATION process{};
    const std::wstring folder = options.workingDirectory.wstring();
    const BOOL ok = CreateProcessW(nullptr, commandLine.data(), nullptr, nullptr, TRUE, 0, nullptr,
                                   folder.empty() ? nullptr : folder.c_str(), &startup, &process);
    if (out != INVALID_HANDLE_VALUE) CloseHandle(out);
    if (!ok) {
        result.error = "cannot run " + argv[0] + " (error " + std::to_string(GetLastError()) + ")";
        return result;
    }
    const DWORD limit = options.timeLimit > 0. ? DWORD(options.timeLimit * 1000.) : INFINITE;
    if (WaitForSingleObject(process.hProcess, limit) == WAIT_TIMEOUT) {
        TerminateProcess(process.hProcess, 1);
        WaitForSingleObject(process.hProcess, INFINITE);
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

// Waits for `pid` into `status`, killing it once `timeLimit` seconds (> 0) have passed: a program
// that hangs is stopped, not waited for. Returns 0, or the errno of a wait that failed.
int waitFor(pid_t pid, double timeLimit, int& status) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeLimit);
    for (;;) {
        const pid_t done = waitpid(pid, &status, timeLimit > 0. ? WNOHANG : 0);
        if (done == pid) return 0;
        if (done < 0 && errno != EINTR) return errno;
        if (done == 0) {
            if (std::chrono::steady_clock::now() > deadline) kill(pid, SIGKILL);
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
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
    if (!options.output.empty()) {
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
    if (error != 0) {
        result.error = "cannot run " + argv[0] + ": " + std::strerror(error);
        return result;
    }
    const RunningProcess running(pid);
    int status = 0;
    if (const int lost = waitFor(pid, options.timeLimit, status); lost != 0) {
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
