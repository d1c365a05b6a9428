// The guard around a running agent: the signals it could send the grader (without a PID namespace)
// are recorded against it, and the processes it leaves are adopted, then swept.
#include "grader/sandbox/sandbox_internal.h"

#ifdef RAYLAB_POSIX_SANDBOX

#include "grader/sandbox/process.h"
#include "src/messages.h"

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <dirent.h>
#include <fcntl.h>
#include <mutex>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#ifdef __linux__
#include <sys/prctl.h>
#endif

namespace raylab::grader::detail {

namespace {

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
// This process's parent when the guard began: its signals are never an agent's, the one its death
// sends (PR_SET_PDEATHSIG, from a grade-class run killed with SIGKILL) included, though by then this
// process has another parent and the sender is gone.
std::atomic<long> g_parent{0};

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
    if (sent && info->si_pid != getpid() && info->si_pid != g_parent.load()) {
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

} // namespace

ChildGuard::ChildGuard(bool guardSignals) : m_signals(guardSignals) {
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
    g_parent.store(getppid());
    struct sigaction action{};
    action.sa_sigaction = onSignal;
    action.sa_flags = SA_SIGINFO | SA_RESTART;
    sigemptyset(&action.sa_mask);
    for (int s : kGuardedSignals) sigaction(s, &action, &g_previous[s]);
}

void ChildGuard::stopGuarding() {
    std::lock_guard lock(g_guardMutex);
    if (m_signals && --g_signalGuards == 0)
        for (int s : kGuardedSignals) sigaction(s, &g_previous[s], nullptr);
    m_signals = false;
    while (g_handlersRunning.load() > 0) std::this_thread::yield();
}

ChildGuard::~ChildGuard() {
    stopGuarding();
    std::lock_guard lock(g_guardMutex);
    if (m_slot) m_slot->store(0);
#ifdef __linux__
    if (--g_adopters == 0) prctl(PR_SET_CHILD_SUBREAPER, 0);
#endif
}

void ChildGuard::started(long agent) {
    m_agent = agent;
    if (m_slot) m_slot->store(agent);
}

std::vector<std::string> ChildGuard::violations() const {
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

} // namespace raylab::grader::detail

#endif
