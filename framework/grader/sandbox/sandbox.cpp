#include "grader/sandbox/sandbox.h"

#include "grader/sandbox/process.h"
#include "src/messages.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <mutex>
#include <optional>
#include <sstream>
#include <stdexcept>

#if defined(__unix__) || defined(__APPLE__)
#define RAYLAB_POSIX_SANDBOX 1
#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <dirent.h>
#include <fcntl.h>
#include <poll.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#endif
#ifdef __linux__
#include <sys/prctl.h>
#include <sys/syscall.h>
#endif

// An ASan build's agents reserve terabytes of shadow memory: an address-space limit kills them at
// start, so memory is guarded by ASan's own limits there.
#if defined(__SANITIZE_ADDRESS__)
#define RAYLAB_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define RAYLAB_ASAN 1
#endif
#endif

namespace raylab::grader {

namespace fs = std::filesystem;

std::string AgentRun::describe() const {
    std::string text;
    if (timedOut) text = tr("sandbox.timed_out");
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

using Clock = std::chrono::steady_clock;

Clock::duration seconds(double s) {
    return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(s));
}

// The child ends its channel when it exits; one that closes it and lives on gets this long.
constexpr double kGraceAfterChannelClosed = 2.;

// The descriptors the agent finds its channels on (after stdin, stdout and stderr).
constexpr int kReportFd = 3;
constexpr int kRequestFd = 4;

// ---- bubblewrap ---------------------------------------------------------------------------

// The namespaces and limits of every bubblewrap run (the probe below tries them all).
const char* const kBubblewrapIsolation[] = {"--unshare-pid", "--unshare-net", "--unshare-ipc", "--unshare-uts",
                                            "--unshare-cgroup-try", "--die-with-parent", "--new-session",
                                            "--cap-drop", "ALL"};

// bwrap in PATH, and whether it can make its namespaces here (a container may forbid them).
struct BubblewrapProbe {
    fs::path program; // empty: not installed
    bool works = false;
};

const BubblewrapProbe& bubblewrapProbe() {
    static const BubblewrapProbe found = [] {
        BubblewrapProbe probe;
#ifdef __linux__
        probe.program = findProgram("bwrap");
        if (probe.program.empty()) return probe;
        std::vector<std::string> argv{probe.program.string()};
        argv.insert(argv.end(), std::begin(kBubblewrapIsolation), std::end(kBubblewrapIsolation));
        argv.insert(argv.end(), {"--ro-bind", "/", "/", "--", "/bin/true"});
        probe.works = runProcess(argv, {{}, "/dev/null"}).succeeded();
#endif
        return probe;
    }();
    return found;
}

// bwrap, when it can confine agents here.
fs::path bubblewrap() {
    const BubblewrapProbe& probe = bubblewrapProbe();
    return probe.works ? probe.program : fs::path();
}

// Said once a run: grading without bubblewrap is a choice the instructor must know about.
void sayOnceWithoutBubblewrap(bool turnedOff) {
    static std::once_flag once;
    std::call_once(once, [turnedOff] {
#ifdef __linux__
        const std::string why = turnedOff ? tr("sandbox.bubblewrap_turned_off") : bubblewrapMissing();
        std::fprintf(stderr, "%s\n", tr("sandbox.without_bubblewrap", {{"why", why}}).c_str());
#else
        (void)turnedOff;
        std::fprintf(stderr, "%s\n", tr("sandbox.without_bubblewrap_here").c_str());
#endif
    });
}

void addBind(std::vector<std::string>& args, const char* how, const fs::path& path) {
    args.insert(args.end(), {how, path.string(), path.string()});
}

// bwrap's arguments before the program: the system read-only, the given files, nothing else.
std::vector<std::string> bubblewrapArgs(const fs::path& bwrap, const AgentCommand& c) {
    std::vector<std::string> args{bwrap.string()};
    args.insert(args.end(), std::begin(kBubblewrapIsolation), std::end(kBubblewrapIsolation));
    args.insert(args.end(), {"--ro-bind", "/usr", "/usr", "--proc", "/proc", "--dev", "/dev", "--tmpfs", "/tmp"});
    // /lib, /bin ... are links into /usr on merged systems, folders elsewhere.
    for (const char* top : {"/bin", "/sbin", "/lib", "/lib32", "/lib64", "/libx32"}) {
        std::error_code error;
        if (fs::is_symlink(top, error)) args.insert(args.end(), {"--symlink", fs::read_symlink(top).string(), top});
        else if (fs::is_directory(top, error)) addBind(args, "--ro-bind", top);
    }
    for (const char* file : {"/etc/ld.so.cache", "/etc/ld.so.conf", "/etc/ld.so.conf.d", "/etc/localtime"})
        addBind(args, "--ro-bind-try", file);
    addBind(args, "--bind", c.scratch);
    for (const fs::path& folder : c.writable) addBind(args, "--bind", folder);
    for (const fs::path& input : c.readable) addBind(args, "--ro-bind-try", input);
    addBind(args, "--ro-bind", c.program);
    args.insert(args.end(), {"--chdir", c.scratch.string(), "--"});
    return args;
}

// ---- the child's side ------------------------------------------------------------------------

void limit(int resource, unsigned long long value) {
    rlimit r{rlim_t(value), rlim_t(value)};
    setrlimit(resource, &r);
}

// Everything the child needs, prepared before fork (after it, only async-signal-safe calls).
struct ChildPlan {
    std::vector<std::string> argv, env;
    std::vector<char*> cargv, cenv;
    fs::path scratch;
    SandboxLimits limits;
    int reportFd = -1, requestFd = -1;

    void seal() {
        for (std::string& a : argv) cargv.push_back(a.data());
        cargv.push_back(nullptr);
        for (std::string& e : env) cenv.push_back(e.data());
        cenv.push_back(nullptr);
    }
};

[[noreturn]] void execChild(const ChildPlan& plan) {
    setsid(); // its own session and process group: the parent stops them all at once
#ifdef __linux__
    prctl(PR_SET_PDEATHSIG, SIGKILL); // and it dies with the grader's thread that started it
#endif
    if (chdir(plan.scratch.c_str()) != 0) _exit(126);
    const int out = open("stdout.txt", O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    const int err = open("stderr.txt", O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    const int null = open("/dev/null", O_RDONLY | O_CLOEXEC);
    // The channels, moved above the numbers they will take so that no dup2 overwrites the other.
    const int report = fcntl(plan.reportFd, F_DUPFD_CLOEXEC, 10);
    const int request = plan.requestFd >= 0 ? fcntl(plan.requestFd, F_DUPFD_CLOEXEC, 10) : -1;
    if (out < 0 || err < 0 || null < 0 || report < 0 || (plan.requestFd >= 0 && request < 0)) _exit(126);
    if (dup2(null, 0) < 0 || dup2(out, 1) < 0 || dup2(err, 2) < 0 || dup2(report, kReportFd) < 0) _exit(126);
    if (request >= 0 && dup2(request, kRequestFd) < 0) _exit(126);
    // Nothing else of the grader's stays open in the child (a class's lock, another student's file).
    for (int fd = kRequestFd + 1; fd < 1024; ++fd) close(fd);
    // At the soft limit SIGXCPU says why; the hard limit, a second later, kills one that ignores it.
    const rlimit cpu{rlim_t(plan.limits.cpuSeconds), rlim_t(plan.limits.cpuSeconds + 1)};
    setrlimit(RLIMIT_CPU, &cpu);
#ifndef RAYLAB_ASAN
    limit(RLIMIT_AS, plan.limits.memoryBytes);
#endif
    limit(RLIMIT_FSIZE, plan.limits.fileBytes);
    limit(RLIMIT_CORE, 0);
    execve(plan.cargv[0], plan.cargv.data(), plan.cenv.data());
    _exit(127);
}

// A small environment: the grader's variables are none of the child's business.
std::vector<std::string> childEnvironment(const AgentCommand& c, const SandboxLimits& limits) {
    std::vector<std::string> env{"PATH=/usr/bin:/bin", "HOME=" + c.scratch.string(), "LC_ALL=C"};
    for (const char* name : {"UBSAN_OPTIONS", "LSAN_OPTIONS"})
        if (const char* value = std::getenv(name)) env.push_back(std::string(name) + "=" + value);
#ifdef RAYLAB_ASAN
    const std::string megabytes = std::to_string(limits.memoryBytes >> 20);
    const char* given = std::getenv("ASAN_OPTIONS");
    env.push_back("ASAN_OPTIONS=" + std::string(given ? given : "") + (given && *given ? ":" : "") +
                  "hard_rss_limit_mb=" + megabytes + ":max_allocation_size_mb=" + megabytes +
                  ":allocator_may_return_null=1" +
                  // a crash ends the agent with its signal, as in a release build, for the same report
                  ":handle_segv=0:handle_sigbus=0:handle_sigfpe=0");
#else
    (void)limits;
    if (const char* given = std::getenv("ASAN_OPTIONS")) env.push_back(std::string("ASAN_OPTIONS=") + given);
#endif
    return env;
}

// ---- signals from the child, without bubblewrap ---------------------------------------------------

// The agents running without a PID namespace (their pid is their session and group), and what they
// tried: lock-free, for the signal handler.
constexpr int kMaxAgents = 32;
std::atomic<long> g_agents[kMaxAgents];
struct Violation {
    std::atomic<long> agent{0};
    std::atomic<int> signal{0};
};
constexpr unsigned kMaxViolations = 64;
Violation g_violations[kMaxViolations];
std::atomic<int> g_violationCount{0};

// The signals that end or stop a process by default; SIGKILL and SIGSTOP cannot be caught
// (docs/grading.md says so).
constexpr int kGuardedSignals[] = {SIGHUP,  SIGINT,  SIGQUIT, SIGILL,    SIGTRAP, SIGABRT, SIGBUS,
                                   SIGFPE,  SIGUSR1, SIGSEGV, SIGUSR2,   SIGPIPE, SIGALRM, SIGTERM,
                                   SIGTSTP, SIGTTIN, SIGTTOU, SIGVTALRM, SIGPROF, SIGXCPU, SIGXFSZ, SIGSYS};
struct sigaction g_previous[NSIG];
std::mutex g_guardMutex;
int g_adopters = 0, g_signalGuards = 0;

bool isAgent(long pid) {
    for (const std::atomic<long>& a : g_agents)
        if (pid != 0 && a.load() == pid) return true;
    return false;
}

// The parent of `pid`, from /proc (open and read are async-signal-safe); 0 when unknown.
long parentOf(long pid) {
#ifdef __linux__
    char path[64] = "/proc/";
    char digits[24];
    int n = 0;
    for (long v = pid; v > 0 && n < 20; v /= 10) digits[n++] = char('0' + v % 10);
    int at = 6;
    while (n > 0) path[at++] = digits[--n];
    std::memcpy(path + at, "/stat", 6);
    const int fd = open(path, O_RDONLY | O_CLOEXEC);
    if (fd < 0) return 0;
    char text[512];
    const ssize_t size = read(fd, text, sizeof text - 1);
    close(fd);
    if (size <= 0) return 0;
    text[size] = 0;
    const char* end = std::strrchr(text, ')'); // the name may hold anything but ends there
    if (!end || end[1] == 0 || end[2] == 0) return 0;
    const char* p = end + 3; // after ") S "
    while (*p && *p != ' ') ++p;
    long parent = 0;
    for (++p; *p >= '0' && *p <= '9'; ++p) parent = parent * 10 + (*p - '0');
    return parent;
#else
    (void)pid;
    return 0;
#endif
}

// An agent between fork and its registration (its pid not known to the parent yet).
constexpr long kStarting = -1;

// The agent whose tree `pid` is in (kStarting when it is one that has just started), or 0. A process
// an agent left behind is either still below it, in its session or group, or an orphan the grader
// adopted (a subreaper) and did not start.
long agentOf(long pid) {
    long anyAgent = 0;
    for (const std::atomic<long>& a : g_agents)
        if (a.load() != 0) anyAgent = a.load();
    if (anyAgent == 0) return 0;
    const long self = getpid();
    for (int depth = 0; depth < 64 && pid > 1 && pid != self; ++depth) {
        if (isAgent(pid)) return pid;
        const long session = getsid(pid_t(pid));
        if (session < 0 && errno == ESRCH) return anyAgent; // gone already: only a child races away so fast
        if (isAgent(session)) return session;
        if (isAgent(getpgid(pid_t(pid)))) return getpgid(pid_t(pid));
        const long parent = parentOf(pid);
        if (parent == self) return isRunningProcess(pid) ? 0 : anyAgent; // adopted, or not registered yet
        pid = parent;
    }
    return 0;
}

void forward(int signal, siginfo_t* info, void* context, bool sent) {
    const struct sigaction& previous = g_previous[signal];
    if (previous.sa_flags & SA_SIGINFO) {
        if (previous.sa_sigaction) previous.sa_sigaction(signal, info, context);
    } else if (previous.sa_handler == SIG_DFL) {
        if (signal == SIGTSTP || signal == SIGTTIN || signal == SIGTTOU) {
            raise(SIGSTOP); // stopped as before, and still guarded once continued
            return;
        }
        ::signal(signal, SIG_DFL); // delivered as before once this handler returns (a fault recurs)
        if (sent) raise(signal);
    } else if (previous.sa_handler != SIG_IGN && previous.sa_handler) {
        previous.sa_handler(signal);
    }
}

// Handlers running now, in any thread: a guard that ends waits for them before it forgets its agent.
std::atomic<int> g_handlersRunning{0};

void onSignal(int signal, siginfo_t* info, void* context) {
    const int savedErrno = errno;
    ++g_handlersRunning;
    const bool sent = info->si_code == SI_USER || info->si_code == SI_QUEUE
#ifdef SI_TKILL
                      || info->si_code == SI_TKILL
#endif
        ;
    if (sent && info->si_pid != getpid()) {
        if (const long agent = agentOf(info->si_pid)) {
            Violation& v = g_violations[unsigned(g_violationCount.fetch_add(1)) % kMaxViolations]; // a ring
            v.signal.store(signal);
            v.agent.store(agent);
            --g_handlersRunning;
            errno = savedErrno;
            return; // recorded against the agent, otherwise ignored
        }
    }
    --g_handlersRunning;
    forward(signal, info, context, sent);
    errno = savedErrno;
}

// While an agent runs, the grader adopts (as a subreaper) the processes it leaves, so that the
// sweep finds them, even bubblewrap's init once bubblewrap has gone. Without a PID namespace it
// also takes the signals the agent could send it.
class ChildGuard {
public:
    // Before the fork: from its first instruction, the child is guarded against.
    explicit ChildGuard(bool guardSignals) : m_signals(guardSignals) {
        std::lock_guard lock(g_guardMutex);
        for (std::atomic<long>& slot : g_agents) {
            long empty = 0;
            if (slot.compare_exchange_strong(empty, kStarting)) {
                m_slot = &slot;
                break;
            }
        }
#ifdef __linux__
        if (g_adopters++ == 0) prctl(PR_SET_CHILD_SUBREAPER, 1);
#endif
        if (!m_signals || g_signalGuards++ > 0) return;
        struct sigaction action{};
        action.sa_sigaction = onSignal;
        action.sa_flags = SA_SIGINFO | SA_RESTART;
        sigemptyset(&action.sa_mask);
        for (int s : kGuardedSignals) sigaction(s, &action, &g_previous[s]);
    }
    // Once the agent's tree is gone: the grader's own handlers are back, and a handler another thread
    // is still in has found this agent (a signal sent before its end) and recorded what it did.
    void stopGuarding() {
        std::lock_guard lock(g_guardMutex);
        if (m_signals && --g_signalGuards == 0)
            for (int s : kGuardedSignals) sigaction(s, &g_previous[s], nullptr);
        m_signals = false;
        while (g_handlersRunning.load() > 0) std::this_thread::yield();
    }
    ~ChildGuard() {
        stopGuarding();
        std::lock_guard lock(g_guardMutex);
        if (m_slot) m_slot->store(0);
#ifdef __linux__
        if (--g_adopters == 0) prctl(PR_SET_CHILD_SUBREAPER, 0);
#endif
    }
    void started(long agent) {
        m_agent = agent;
        if (m_slot) m_slot->store(agent);
    }

    // What the agent tried (also while it was starting), taken from the shared record.
    std::vector<std::string> violations() const {
        std::vector<std::string> found;
        for (Violation& v : g_violations) {
            const long from = v.agent.load();
            if (from == 0 || (from != m_agent && from != kStarting)) continue;
            found.push_back(tr("sandbox.signalled_grader", {{"signal", std::to_string(v.signal.load())},
                                                            {"name", strsignal(v.signal.load())}}));
            v.agent.store(0);
        }
        return found;
    }

    ChildGuard(const ChildGuard&) = delete;
    ChildGuard& operator=(const ChildGuard&) = delete;

private:
    bool m_signals;
    long m_agent = 0;
    std::atomic<long>* m_slot = nullptr;
};

// Every process of the agent's session, and every orphan the grader adopted and did not start:
// killed and reaped until none is left (a fork loop refills the list a few times). Bubblewrap's
// init is one: it is reaped only once every process of its namespace is gone.
void sweep(long agent) {
#ifdef __linux__
    const long self = getpid();
    for (int pass = 0; pass < 100; ++pass) {
        kill(pid_t(-agent), SIGKILL);
        std::vector<long> found;
        if (DIR* proc = opendir("/proc")) {
            while (const dirent* entry = readdir(proc)) {
                char* end = nullptr;
                const long pid = std::strtol(entry->d_name, &end, 10);
                if (pid <= 1 || *end != 0 || pid == self || isAgent(pid) || isRunningProcess(pid)) continue;
                const long session = getsid(pid_t(pid));
                if (session == agent || parentOf(pid) == self) found.push_back(pid);
            }
            closedir(proc);
        }
        if (found.empty()) return;
        for (long pid : found) kill(pid_t(pid), SIGKILL);
        for (long pid : found)
            if (parentOf(pid) == self) waitpid(pid_t(pid), nullptr, 0);
    }
#else
    kill(pid_t(-agent), SIGKILL);
#endif
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
pid_t startChild(const AgentCommand& c, const SandboxLimits& limits, const fs::path& bwrap, int reportFd, int requestFd) {
    ChildPlan plan;
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
            if (m_received.size() < kMaxBytes) m_received.append(m_buffer, std::size_t(n));
            m_deadline = std::min(m_end, Clock::now() + seconds(m_limits.wallSeconds)); // it spoke: a new item's time
        }
    }

    static constexpr std::size_t kMaxBytes = 64u << 20; // more than any honest report
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
    const fs::path bwrap = limits.bubblewrap ? bubblewrap() : fs::path();
    if (bwrap.empty()) sayOnceWithoutBubblewrap(!limits.bubblewrap);
    int report[2], request[2] = {-1, -1};
    if (!openPipe(report) || !openPipe(request))
        throw std::runtime_error("grader: cannot open a pipe to the agent");
    // Without a PID namespace the child could reach the grader: its signals are guarded too.
    std::optional<ChildGuard> guard(std::in_place, bwrap.empty());
    const pid_t pid = startChild(c, limits, bwrap, report[1], request[0]);
    guard->started(pid);
    close(report[1]);
    close(request[0]);
    AgentWatch watch(pid, report[0], request[1], limits, c.requests);
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
    return limits.bubblewrap && !bubblewrap().empty() ? "bubblewrap" : "process group";
#else
    (void)limits;
    return "none";
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
    (void)limits;
    const fs::path results = c.scratch / "results.jsonl", requestFile = c.scratch / "requests.jsonl";
    fs::remove(results);
    std::ofstream(requestFile, std::ios::binary) << c.requests;
    std::vector<std::string> argv{c.program.string()};
    argv.insert(argv.end(), c.args.begin(), c.args.end());
    argv.insert(argv.end(), {"--request-file", requestFile.string(), "--report-file", results.string()});
    const ProcessResult ran = runProcess(argv, {c.scratch, c.scratch / "stderr.txt"});
    run.exitCode = ran.exitCode;
    std::ifstream in(results, std::ios::binary);
    std::stringstream all;
    all << in.rdbuf();
    run.lines = splitLines(all.str());
#endif
    run.stderrTail = tail(c.scratch / "stderr.txt");
    return run;
}

} // namespace raylab::grader
