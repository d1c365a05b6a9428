#include "grader/sandbox/sandbox.h"

#include "grader/sandbox/cgroup.h"
#include "grader/sandbox/install_command.h"
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
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#endif

namespace raylab::grader {

namespace fs = std::filesystem;

namespace {

// "256 MB", "4 GB".
std::string sizeText(unsigned long long bytes) {
    constexpr unsigned long long kGB = 1ull << 30, kMB = 1ull << 20;
    if (bytes >= kGB && bytes % kGB == 0) return std::to_string(bytes / kGB) + " GB";
    return std::to_string((bytes + kMB - 1) / kMB) + " MB";
}

} // namespace

std::string AgentRun::describe() const {
    std::string text;
    if (processLimit) text = tr("sandbox.process_limit", {{"count", std::to_string(limits.processes)}});
    else if (memoryLimit) text = tr("sandbox.memory_limit", {{"size", sizeText(limits.memoryBytes)}});
    else if (diskLimit) text = tr("sandbox.disk_limit", {{"size", sizeText(limits.diskBytes)}});
    else if (timedOut) text = tr("sandbox.timed_out");
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
                 const RunCgroup& cgroup, int landlock, int reportFd, int requestFd) {
    ChildPlan plan;
    plan.user = user;
    plan.landlock = landlock;
    if (cgroup.active()) plan.cgroup = &cgroup.joinFiles();
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

// What a file or folder (an agent's scratch folder, its /tmp included) takes on disk: blocks, so that
// a sparse file counts what it holds. Links are not followed; a file removed during the walk ends it
// early (the next look counts).
unsigned long long diskUsed(const fs::path& path) {
    struct stat file;
    if (lstat(path.c_str(), &file) != 0) return 0;
    unsigned long long used = static_cast<unsigned long long>(file.st_blocks) * 512u;
    if (!S_ISDIR(file.st_mode)) return used;
    std::error_code error;
    for (fs::recursive_directory_iterator it(path, fs::directory_options::skip_permission_denied, error), end;
         !error && it != end; it.increment(error))
        if (lstat(it->path().c_str(), &file) == 0) used += static_cast<unsigned long long>(file.st_blocks) * 512u;
    return used;
}

// The fallback's /tmp is the machine's (no mount namespace): what the agent's user makes there during
// the run counts with its scratch folder, and is removed once the run is over.
class SharedTmp {
public:
    explicit SharedTmp(const UnprivilegedUser* user) : m_user(user) {
        if (m_user) m_before = entries();
    }
    ~SharedTmp() {
        std::error_code ignored;
        for (const fs::path& made : created()) fs::remove_all(made, ignored); // links are removed, not followed
    }
    SharedTmp(const SharedTmp&) = delete;
    SharedTmp& operator=(const SharedTmp&) = delete;

    unsigned long long used() const {
        unsigned long long total = 0;
        for (const fs::path& made : created()) total += diskUsed(made);
        return total;
    }

private:
    std::vector<fs::path> entries() const {
        std::vector<fs::path> found;
        std::error_code error;
        for (fs::directory_iterator it("/tmp", error), end; !error && it != end; it.increment(error))
            found.push_back(it->path());
        std::sort(found.begin(), found.end());
        return found;
    }
    // Made during the run by the agent's user.
    std::vector<fs::path> created() const {
        std::vector<fs::path> made;
        if (!m_user) return made;
        for (const fs::path& entry : entries()) {
            struct stat file;
            if (!std::binary_search(m_before.begin(), m_before.end(), entry) && lstat(entry.c_str(), &file) == 0 &&
                file.st_uid == m_user->uid)
                made.push_back(entry);
        }
        return made;
    }

    const UnprivilegedUser* m_user;
    std::vector<fs::path> m_before;
};

// The limits the parent watches while the agent runs, looked at every kMeterPeriod: everything it
// wrote, and its cgroup's (a fork refused there is a fork bomb, a process killed at the memory limit
// leaves the others holding it: the run is stopped at once).
constexpr double kMeterPeriod = 0.1;

struct RunMeter {
    const fs::path& scratch;
    const SharedTmp& tmp;
    const RunCgroup& cgroup;
    const SandboxLimits& limits;

    // Whether it went past one, which is recorded in `run`.
    bool overLimit(AgentRun& run) const {
        run.processLimit = cgroup.processLimitHit();
        run.memoryLimit = cgroup.memoryLimitHit();
        run.diskLimit = !run.processLimit && !run.memoryLimit && diskUsed(scratch) + tmp.used() > limits.diskBytes;
        return run.processLimit || run.memoryLimit || run.diskLimit;
    }
};

// How a watch ended.
enum class WatchEnd { exited, timedOut, overLimit };

// The parent's side of a running agent: its channel read as it comes, its requests written as it
// reads them, until it exits, runs out of time or goes past a limit the meter watches.
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

    // Until the child exits (its wait status in `status`), its time is up or it goes past a limit.
    WatchEnd wait(int& status, const RunMeter& meter, AgentRun& run) {
        Clock::time_point nextLook = Clock::now();
        for (;;) {
            if (m_requestFd >= 0 && m_pending.empty()) { // all written: the child reads end-of-file
                close(m_requestFd);
                m_requestFd = -1;
            }
            const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(m_deadline - Clock::now()).count();
            if (left <= 0) return WatchEnd::timedOut;
            if (Clock::now() >= nextLook) {
                if (meter.overLimit(run)) return WatchEnd::overLimit;
                nextLook = Clock::now() + seconds(kMeterPeriod);
            }
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
                return WatchEnd::exited;
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
    // Bubblewrap's /tmp is a folder of its scratch, on disk, where its disk limit counts it.
    if (!bwrap.empty()) fs::create_directories(agentTmp(c.scratch));
    const RunCgroup cgroup(limits.processes, limits.memoryBytes);
    const SharedTmp tmp(bwrap.empty() ? user : nullptr);
    int report[2], request[2] = {-1, -1};
    if (!openPipe(report) || !openPipe(request))
        throw std::runtime_error("grader: cannot open a pipe to the agent");
    // Without a PID namespace the child could reach the grader: its signals are guarded too.
    std::optional<ChildGuard> guard(std::in_place, bwrap.empty());
    const pid_t pid = startChild(staged, limits, bwrap, user, cgroup, landlock ? landlock->fd() : -1, report[1], request[0]);
    guard->started(pid);
    close(report[1]);
    close(request[0]);
    AgentWatch watch(pid, report[0], request[1], limits, staged.requests);
    AgentRun run;
    int status = 0;
    const WatchEnd end = watch.wait(status, RunMeter{c.scratch, tmp, cgroup, limits}, run);
    run.timedOut = end == WatchEnd::timedOut;
    // Whatever it started is stopped too: the PID namespace goes with bwrap, the session is swept.
    kill(-pid, SIGKILL);
    if (end != WatchEnd::exited) waitpid(pid, &status, 0);
    sweep(pid);
    guard->stopGuarding();
    run.violations = guard->violations();
    guard.reset();
    // A limit reached as it ended: a fork refused, a process the kernel killed for the memory of all.
    run.processLimit = run.processLimit || cgroup.processLimitHit();
    run.memoryLimit = run.memoryLimit || cgroup.memoryLimitHit();
    if (end == WatchEnd::exited) {
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
    return tr("sandbox.bubblewrap_not_installed", {{"install", installCommand("bubblewrap", "", "")}});
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
    run.limits = limits;
    collectOutput(c.scratch, run);
    return run;
}

} // namespace raylab::grader