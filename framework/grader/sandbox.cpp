#include "grader/sandbox.h"

#include "raylab/messages.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#if defined(__unix__) || defined(__APPLE__)
#define RAYLAB_POSIX_SANDBOX 1
#include <cerrno>
#include <chrono>
#include <csignal>
#include <fcntl.h>
#include <poll.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <algorithm>
#include <thread>
#include <unistd.h>
#endif

namespace raylab::grader {

namespace fs = std::filesystem;

std::string AgentRun::describe() const {
    if (timedOut) return tr("sandbox.timed_out");
    if (signal != 0) {
#ifdef RAYLAB_POSIX_SANDBOX
        if (signal == SIGXCPU) return tr("sandbox.cpu_limit");
        if (signal == SIGXFSZ) return tr("sandbox.output_limit");
        if (signal == SIGSEGV) return tr("sandbox.segfault");
        if (signal == SIGABRT) return tr("sandbox.aborted");
#endif
        return tr("sandbox.signal", {{"signal", std::to_string(signal)}});
    }
    if (exitCode == 0) return tr("sandbox.exited");
    return tr("sandbox.exit_status", {{"status", std::to_string(exitCode)}});
}

namespace {

std::string tail(const fs::path& file, std::size_t bytes = 2000) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream all;
    all << in.rdbuf();
    const std::string text = all.str();
    return text.size() > bytes ? "..." + text.substr(text.size() - bytes) : text;
}

std::vector<std::string> splitLines(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        if (!line.empty()) lines.push_back(line);
    return lines;
}

#ifdef RAYLAB_POSIX_SANDBOX

void limit(int resource, unsigned long long value) {
    rlimit r{rlim_t(value), rlim_t(value)};
    setrlimit(resource, &r);
}

[[noreturn]] void execChild(const fs::path& program, std::vector<std::string> args, const fs::path& scratch,
                            const SandboxLimits& limits, int readFd, int writeFd) {
    setpgid(0, 0); // its own group: the parent can stop it and any process it starts
    if (chdir(scratch.c_str()) != 0) _exit(126);
    const int out = open("stdout.txt", O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err = open("stderr.txt", O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int null = open("/dev/null", O_RDONLY);
    if (out < 0 || err < 0 || null < 0) _exit(126);
    dup2(null, 0);
    dup2(out, 1);
    dup2(err, 2);
    limit(RLIMIT_CPU, (unsigned long long)limits.cpuSeconds);
    limit(RLIMIT_AS, limits.memoryBytes);
    limit(RLIMIT_FSIZE, limits.fileBytes);
    limit(RLIMIT_CORE, 0);
    args.insert(args.begin(), program.string());
    args.push_back("--request-fd");
    args.push_back(std::to_string(readFd));
    args.push_back("--report-fd");
    args.push_back(std::to_string(writeFd));
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    execv(program.c_str(), argv.data());
    _exit(127);
}

// A pipe holding all of `requests`, its write end closed: the child reads them at its pace, and
// the parent never blocks on (or is signalled by) a child that stops reading.
int requestPipe(const std::string& requests) {
    int fds[2];
    if (pipe(fds) != 0) throw std::runtime_error("grader: cannot open a pipe to the agent");
#ifdef F_SETPIPE_SZ
    if (requests.size() > 65536) fcntl(fds[1], F_SETPIPE_SZ, int(std::min<std::size_t>(requests.size() + 4096, 1u << 20)));
#endif
    fcntl(fds[1], F_SETFL, O_NONBLOCK);
    std::size_t written = 0;
    while (written < requests.size()) {
        const ssize_t n = write(fds[1], requests.data() + written, requests.size() - written);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            close(fds[0]);
            close(fds[1]);
            throw std::runtime_error("grader: the requests (" + std::to_string(requests.size()) + " bytes) do not fit in a pipe");
        }
        written += std::size_t(n);
    }
    close(fds[1]);
    return fds[0];
}

AgentRun runPosix(const fs::path& program, const std::vector<std::string>& args, const fs::path& scratch,
                  const SandboxLimits& limits, const std::string& requests) {
    const int requestFd = requestPipe(requests);
    int fds[2];
    if (pipe(fds) != 0) {
        close(requestFd);
        throw std::runtime_error("grader: cannot open a pipe to the agent");
    }
    std::fflush(nullptr);
    const pid_t pid = fork();
    if (pid < 0) throw std::runtime_error("grader: cannot start " + program.string());
    if (pid == 0) {
        close(fds[0]);
        execChild(program, args, scratch, limits, requestFd, fds[1]);
    }
    close(requestFd);
    close(fds[1]);
    setpgid(pid, pid); // also here, so the group exists whoever runs first
    AgentRun run;
    using Clock = std::chrono::steady_clock;
    const auto seconds = [](double s) { return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(s)); };
    const Clock::time_point end = Clock::now() + seconds(limits.totalSeconds);
    Clock::time_point deadline = std::min(end, Clock::now() + seconds(limits.wallSeconds));
    auto remainingMs = [&] {
        return int(std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count());
    };
    std::string received;
    const std::size_t maxBytes = 64u << 20; // more than any honest report (every figure's pixels: about 10 MB)
    char buffer[65536];
    for (;;) {
        const int wait = remainingMs();
        if (wait <= 0) {
            run.timedOut = true;
            break;
        }
        pollfd p{fds[0], POLLIN, 0};
        const int ready = poll(&p, 1, wait);
        if (ready < 0 && errno == EINTR) continue;
        if (ready <= 0) continue;
        const ssize_t n = read(fds[0], buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break; // every writer closed: the agent ended
        if (received.size() < maxBytes) received.append(buffer, std::size_t(n));
        deadline = std::min(end, Clock::now() + seconds(limits.wallSeconds)); // it spoke: a new item's time
    }
    close(fds[0]);
    int status = 0;
    for (;;) { // the pipe may close before the process ends; it still gets its deadline
        const pid_t done = waitpid(pid, &status, WNOHANG);
        if (done == pid) break;
        if (remainingMs() <= 0) {
            run.timedOut = true;
            kill(-pid, SIGKILL);
            waitpid(pid, &status, 0);
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    kill(-pid, SIGKILL); // whatever it started is stopped too
    if (!run.timedOut) {
        if (WIFEXITED(status)) run.exitCode = WEXITSTATUS(status);
        if (WIFSIGNALED(status)) run.signal = WTERMSIG(status);
    }
    run.lines = splitLines(received);
    return run;
}

#endif

} // namespace

AgentRun runAgent(const fs::path& program, const std::vector<std::string>& args, const fs::path& scratch,
                  const SandboxLimits& limits, const std::string& requests) {
    fs::create_directories(scratch);
    AgentRun run;
#ifdef RAYLAB_POSIX_SANDBOX
    run = runPosix(fs::absolute(program), args, scratch, limits, requests); // the child changes folder first
#else
    (void)limits;
    const fs::path results = fs::absolute(scratch / "results.jsonl"), requestFile = fs::absolute(scratch / "requests.jsonl");
    fs::remove(results);
    std::ofstream(requestFile, std::ios::binary) << requests;
    std::string command = "\"\"" + program.string() + "\"";
    for (const std::string& a : args) command += " \"" + a + "\"";
    command += " --request-file \"" + requestFile.string() + "\" --report-file \"" + results.string() + "\" > \"" + (scratch / "stdout.txt").string() + "\" 2> \"" +
               (scratch / "stderr.txt").string() + "\"\"";
    run.exitCode = std::system(command.c_str());
    std::ifstream in(results, std::ios::binary);
    std::stringstream all;
    all << in.rdbuf();
    run.lines = splitLines(all.str());
#endif
    run.stderrTail = tail(scratch / "stderr.txt");
    return run;
}

} // namespace raylab::grader
