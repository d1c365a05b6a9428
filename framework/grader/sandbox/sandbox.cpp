#include "grader/sandbox/sandbox.h"

#include "grader/sandbox/job_object.h"
#include "grader/sandbox/landlock.h"
#include "grader/sandbox/process.h"
#include "grader/sandbox/sandbox_internal.h"
#include "grader/sandbox/scratch_file.h"
#include "src/messages.h"

#include <cstdio>
#include <cstdlib>
#include <algorithm>
#include <fstream>
#include <mutex>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string_view>
#ifdef RAYLAB_POSIX_SANDBOX
#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <fcntl.h>
#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>
#endif

namespace raylab::grader {

namespace fs = std::filesystem;

std::string AgentRun::describe() const {
    std::string text;
    if (timedOut) text = tr("sandbox.timed_out");
    else if (cpuLimit) text = tr("sandbox.cpu_limit");
    else if (outputLimit) text = tr("sandbox.output_limit");
#ifdef _WIN32
    // What Windows leaves as the exit status of a process that crashed (an NTSTATUS).
    else if (unsigned(exitCode) == 0xC0000005u || unsigned(exitCode) == 0xC00000FDu) // access violation, stack overflow
        text = tr("sandbox.segfault");
    else if (unsigned(exitCode) == 0xC0000409u) text = tr("sandbox.aborted"); // fail-fast: abort() and its like
#endif
    else if (signal != 0) {
#ifdef RAYLAB_POSIX_SANDBOX
        if (signal == SIGXCPU) text = tr("sandbox.cpu_limit");
        else if (signal == SIGXFSZ) text = tr("sandbox.output_limit");
        else if (signal == SIGSEGV) text = tr("sandbox.segfault");
        else if (signal == SIGABRT) text = tr("sandbox.aborted");
        else
#endif
            text = tr("sandbox.signal", {{"signal", std::to_string(signal)}});
    } else if (exitCode == 0) text = tr("sandbox.exited");
    else text = tr("sandbox.exit_status", {{"status", std::to_string(exitCode)}});
    for (const std::string& v : violations) text += tr("sandbox.and_it", {{"what", v}});
    return text;
}

namespace {

constexpr std::size_t kMaxReportBytes = 64u << 20; // what the parent takes of a report: more than any honest one

// The end of its error output for the report, and its output files cut down to what is kept. A file
// that is no longer a file (a link to the solutions or /etc/shadow, a FIFO, /dev/zero) is never
// read: that is an attack on the grader, and the run earns nothing.
void collectOutput(const fs::path& scratch, AgentRun& run) {
    constexpr std::size_t kReported = 2000;
    for (const char* name : {"stdout.txt", "stderr.txt"}) {
        const ScratchFile output = readScratchFile(scratch / name, kOutputKeptBytes, ScratchKeep::tail, true);
        if (output.refused) {
            run.violations.push_back(tr("sandbox.replaced_output", {{"file", name}}));
        } else if (std::string_view(name) == "stderr.txt") {
            const std::string& text = output.text;
            run.stderrTail = text.size() > kReported ? "..." + text.substr(text.size() - kReported) : text;
        }
    }
}

std::vector<std::string> splitLines(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        if (!line.empty()) lines.push_back(line);
    return lines;
}

#ifdef RAYLAB_POSIX_SANDBOX

using namespace detail;

using Clock = std::chrono::steady_clock;

Clock::duration seconds(double s) {
    return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(s));
}

// The child ends its channel when it exits; one that closes it and lives on gets this long.
constexpr double kGraceAfterChannelClosed = 2.;

// Why bubblewrap does not confine the agents, in the reader's language.
std::string whyNotBubblewrap(const SandboxLimits& limits) {
    if (!limits.bubblewrap) return tr("sandbox.bubblewrap_turned_off");
    const char* asked = std::getenv("RAYLAB_SANDBOX");
    if (asked && std::string_view(asked) == "none") return tr("sandbox.none_asked");
    if (asked && std::string_view(asked) == "fallback") return tr("sandbox.fallback_asked");
    return bubblewrapMissing();
}

// Said once a run: grading without bubblewrap is a choice the instructor must know about.
void sayOnceWithoutBubblewrap(const SandboxLimits& limits, const UnprivilegedUser* user) {
    static std::once_flag once;
    std::call_once(once, [&] {
#ifdef __linux__
        const std::string why = whyNotBubblewrap(limits);
        const std::string said =
            user ? tr("sandbox.fallback", {{"why", why},
                                          {"user", user->name},
                                          {"filter", tr(haveSeccomp() ? "sandbox.with_seccomp" : "sandbox.no_seccomp")},
                                          {"files", tr(landlockAbi() > 0 ? "sandbox.with_landlock" : "sandbox.no_landlock")}})
                 : tr("sandbox.without_bubblewrap", {{"why", why}});
        std::fprintf(stderr, "%s\n", said.c_str());
#else
        (void)limits;
        (void)user;
        std::fprintf(stderr, "%s\n", tr("sandbox.without_bubblewrap_here").c_str());
#endif
    });
}

// ---- the parent's side -------------------------------------------------------------------------

void writePending(int fd, std::string& pending) {
    // A child that closed its end makes write fail with EPIPE, and raises SIGPIPE in this thread:
    // blocked here and taken back, so that it never ends the grader.
    sigset_t pipeSignal, previous;
    sigemptyset(&pipeSignal);
    sigaddset(&pipeSignal, SIGPIPE);
    pthread_sigmask(SIG_BLOCK, &pipeSignal, &previous);
    const ssize_t n = write(fd, pending.data(), pending.size());
    if (n > 0) pending.erase(0, std::size_t(n));
    else if (n < 0 && errno == EPIPE) pending.clear();
#ifdef __linux__
    timespec none{0, 0};
    while (sigtimedwait(&pipeSignal, nullptr, &none) > 0) {
    }
#else
    sigset_t pending;
    int taken = 0;
    sigpending(&pending);
    if (sigismember(&pending, SIGPIPE)) sigwait(&pipeSignal, &taken);
#endif
    pthread_sigmask(SIG_SETMASK, &previous, nullptr);
}

// A pipe neither end of which a process started later inherits by accident.
bool openPipe(int fds[2]) {
    if (pipe(fds) != 0) return false;
    for (int k = 0; k < 2; ++k) fcntl(fds[k], F_SETFD, FD_CLOEXEC);
    return true;
}

void setNonBlocking(int fd) { fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) | O_NONBLOCK); }

// Starts the child (bwrap or the agent itself) with the channels' child ends; returns its pid.
pid_t startChild(const AgentCommand& c, const SandboxLimits& limits, const fs::path& bwrap, const UnprivilegedUser* user,
                 int landlock, int reportFd, int requestFd) {
    ChildPlan plan;
    plan.user = user;
    plan.landlock = landlock;
    if (user) plan.seccomp = &seccompProgram(); // compiled here, before the fork
    if (!bwrap.empty()) plan.argv = bubblewrapArgs(bwrap, c);
    plan.argv.push_back(c.program.string());
    plan.argv.insert(plan.argv.end(), c.args.begin(), c.args.end());
    plan.argv.insert(plan.argv.end(), {"--report-fd", std::to_string(kReportFd)});
    plan.argv.insert(plan.argv.end(), {"--request-fd", std::to_string(kRequestFd)});
    plan.env = childEnvironment(c, limits);
    plan.scratch = c.scratch;
    plan.limits = limits;
    plan.reportFd = reportFd;
    plan.requestFd = requestFd;
    plan.seal();
    std::fflush(nullptr);
    const pid_t pid = fork();
    if (pid < 0) throw std::runtime_error("grader: cannot start " + c.program.string());
    if (pid == 0) execChild(plan);
    return pid;
}

// The parent's side of a running agent: its channel read as it comes, its requests written as it
// reads them, until it exits or runs out of time.
class AgentWatch {
public:
    AgentWatch(pid_t pid, int reportFd, int requestFd, const SandboxLimits& limits, std::string requests)
        : m_pid(pid), m_reportFd(reportFd), m_requestFd(requestFd), m_limits(limits), m_pending(std::move(requests)),
          m_end(Clock::now() + seconds(limits.totalSeconds)), m_deadline(std::min(m_end, Clock::now() + seconds(limits.wallSeconds))) {
        setNonBlocking(m_reportFd);
        setNonBlocking(m_requestFd);
    }
    ~AgentWatch() {
        close(m_reportFd);
        if (m_requestFd >= 0) close(m_requestFd);
    }
    AgentWatch(const AgentWatch&) = delete;
    AgentWatch& operator=(const AgentWatch&) = delete;

    // Until the child exits (true, its wait status in `status`) or its time is up (false).
    bool wait(int& status) {
        for (;;) {
            if (m_requestFd >= 0 && m_pending.empty()) { // all written: the child reads end-of-file
                close(m_requestFd);
                m_requestFd = -1;
            }
            const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(m_deadline - Clock::now()).count();
            if (left <= 0) return false;
            pollfd fds[2] = {{m_channelOpen ? m_reportFd : -1, POLLIN, 0},
                             {m_requestFd, POLLOUT, 0}};
            // Short naps: the child's exit is noticed within 20 ms even while a grandchild holds the pipe.
            poll(fds, 2, int(std::min<long long>(left, 20)));
            if (m_channelOpen && (fds[0].revents & (POLLIN | POLLHUP | POLLERR)) && !drain()) {
                m_channelOpen = false; // every writer closed: the child ended, or it is about to
                m_deadline = std::min(m_deadline, Clock::now() + seconds(kGraceAfterChannelClosed));
            }
            if (fds[1].revents & (POLLOUT | POLLERR | POLLHUP)) writePending(m_requestFd, m_pending);
            if (waitpid(m_pid, &status, WNOHANG) == m_pid) {
                if (m_channelOpen) drain(); // what it wrote just before it went
                return true;
            }
        }
    }

    const std::string& received() const { return m_received; }

private:
    // Reads what is there; false at end-of-file.
    bool drain() {
        for (;;) {
            const ssize_t n = read(m_reportFd, m_buffer, sizeof m_buffer);
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) return n < 0; // EAGAIN: open but empty
            if (m_received.size() < kMaxReportBytes) m_received.append(m_buffer, std::size_t(n));
            m_deadline = std::min(m_end, Clock::now() + seconds(m_limits.wallSeconds)); // it spoke: a new item's time
        }
    }

    pid_t m_pid;
    int m_reportFd, m_requestFd;
    const SandboxLimits& m_limits;
    std::string m_pending; // requests not written yet
    Clock::time_point m_end, m_deadline;
    std::string m_received;
    bool m_channelOpen = true;
    char m_buffer[65536];
};

AgentRun runPosix(const AgentCommand& c, const SandboxLimits& limits) {
    const SandboxMode mode = sandboxMode(limits.bubblewrap);
    const fs::path bwrap = mode == SandboxMode::bubblewrap ? bubblewrap() : fs::path();
    const UnprivilegedUser* user = mode == SandboxMode::unprivileged ? &*unprivilegedUser() : nullptr;
    if (bwrap.empty()) sayOnceWithoutBubblewrap(limits, user);
    // The fallback: the agent's folders are its own, and nothing else of the grader's is writable by it.
    // It runs from copies of its program and inputs that its user can read (a tree under /root is
    // not), and, with Landlock, opens nothing else but the system and its own folders.
    std::optional<AgentStage> stage;
    std::optional<LandlockRuleset> landlock;
    AgentCommand staged = c;
    if (user) {
        std::vector<fs::path> own = c.writable;
        own.push_back(c.scratch);
        for (const fs::path& folder : own)
            if (!handOver(folder, *user))
                throw std::runtime_error("grader: cannot give " + folder.string() + " to the user " + user->name);
        stage.emplace(c.program, c.readable);
        staged.program = stage->program();
        staged.readable = stage->readable();
        staged.requests = stage->renamed(c.requests);
        LandlockRules rules = systemRules();
        rules.execute.push_back(staged.program);
        rules.read.insert(rules.read.end(), staged.readable.begin(), staged.readable.end());
        rules.read.emplace_back("/proc"); // as bubblewrap's --proc: another user's processes keep their secrets
        rules.readWrite.insert(rules.readWrite.end(), own.begin(), own.end());
        landlock.emplace(rules);
    }
    int report[2], request[2] = {-1, -1};
    if (!openPipe(report) || !openPipe(request))
        throw std::runtime_error("grader: cannot open a pipe to the agent");
    // Without a PID namespace the child could reach the grader: its signals are guarded too.
    std::optional<ChildGuard> guard(std::in_place, bwrap.empty());
    const pid_t pid = startChild(staged, limits, bwrap, user, landlock ? landlock->fd() : -1, report[1], request[0]);
    guard->started(pid);
    close(report[1]);
    close(request[0]);
    AgentWatch watch(pid, report[0], request[1], limits, staged.requests);
    AgentRun run;
    int status = 0;
    run.timedOut = !watch.wait(status);
    // Whatever it started is stopped too: the PID namespace goes with bwrap, the session is swept.
    kill(-pid, SIGKILL);
    if (run.timedOut) waitpid(pid, &status, 0);
    sweep(pid);
    guard->stopGuarding();
    run.violations = guard->violations();
    guard.reset();
    if (!run.timedOut) {
        if (WIFEXITED(status)) run.exitCode = WEXITSTATUS(status);
        if (WIFSIGNALED(status)) run.signal = WTERMSIG(status);
        // bwrap passes on the child's end: a signal as 128 + its number.
        if (!bwrap.empty() && run.exitCode > 128 && run.exitCode < 128 + NSIG) {
            run.signal = run.exitCode - 128;
            run.exitCode = -1;
        }
    }
    run.lines = splitLines(watch.received());
    return run;
}

#endif

} // namespace

std::string sandboxKind(const SandboxLimits& limits) {
#ifdef RAYLAB_POSIX_SANDBOX
    switch (sandboxMode(limits.bubblewrap)) {
    case SandboxMode::bubblewrap: return "bubblewrap";
    case SandboxMode::unprivileged:
        return std::string("unprivileged user") + (haveSeccomp() ? "" : ", no seccomp filter") +
               (landlockAbi() > 0 ? "" : ", no Landlock");
    case SandboxMode::processGroup: break;
    }
    return "process group";
#else
    (void)limits;
    return "job object";
#endif
}

std::string bubblewrapMissing() {
#ifdef RAYLAB_POSIX_SANDBOX
    const BubblewrapProbe& probe = bubblewrapProbe();
    if (probe.works) return {};
    if (!probe.program.empty()) return tr("sandbox.bubblewrap_no_namespaces", {{"bwrap", probe.program.string()}});
#ifdef __linux__
    return tr("sandbox.bubblewrap_not_installed");
#endif
#endif
    return tr("sandbox.bubblewrap_not_here");
}

AgentRun runAgent(const AgentCommand& command, const SandboxLimits& limits) {
    AgentCommand c = command;
    c.program = fs::absolute(c.program); // the child changes folder first
    c.scratch = fs::absolute(c.scratch);
    fs::create_directories(c.scratch);
    for (fs::path& folder : c.writable) {
        folder = fs::absolute(folder);
        fs::create_directories(folder);
    }
    for (fs::path& input : c.readable) input = fs::absolute(input);
    AgentRun run;
#ifdef RAYLAB_POSIX_SANDBOX
    run = runPosix(c, limits);
#else
    // Said once a run, as with --no-sandbox on Linux: the instructor must know the code is not confined.
    static std::once_flag once;
    std::call_once(once, [] {
        const std::string said = tr("sandbox.without_bubblewrap", {{"why", tr("sandbox.bubblewrap_not_here")}});
        std::fprintf(stderr, "%s\n", said.c_str());
    });
    run = detail::runInJob(c, limits);
    const ScratchFile answers = readScratchFile(c.scratch / "results.jsonl", kMaxReportBytes);
    if (answers.refused) run.violations.push_back(tr("sandbox.replaced_output", {{"file", "results.jsonl"}}));
    run.lines = splitLines(answers.text);
#endif
    collectOutput(c.scratch, run);
    return run;
}

} // namespace raylab::grader