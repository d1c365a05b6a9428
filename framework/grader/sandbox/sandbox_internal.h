#pragma once
// What the sandbox's files share (sandbox.cpp runs an agent with them): bubblewrap's probe and
// arguments (bubblewrap.cpp), the child's limits and environment (child_setup.cpp), the guard
// against the child's signals and the sweep of what it leaves (child_guard.cpp). POSIX only.

#include "grader/sandbox/sandbox.h"

#if defined(__unix__) || defined(__APPLE__)
#define RAYLAB_POSIX_SANDBOX 1
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

#ifdef RAYLAB_POSIX_SANDBOX

#include "grader/sandbox/unprivileged.h"

#include <atomic>
#include <filesystem>
#include <string>
#include <vector>

namespace raylab::grader::detail {

// The descriptors the agent finds its channels on (after stdin, stdout and stderr).
constexpr int kReportFd = 3;
constexpr int kRequestFd = 4;

// The system's folders beside /usr, which a confined program reads and runs: links into /usr on merged
// systems, folders elsewhere.
inline constexpr const char* kSystemTopFolders[] = {"/bin", "/sbin", "/lib", "/lib32", "/lib64", "/libx32"};

// What a confined program sees of /etc (bubblewrap binds them, Landlock allows them): the dynamic
// loader's files, the time zone, and Debian's alternatives (c++ and cc are links through them).
inline constexpr const char* kSystemEtcFiles[] = {"/etc/ld.so.cache", "/etc/ld.so.conf", "/etc/ld.so.conf.d",
                                                  "/etc/localtime", "/etc/alternatives"};

// ---- bubblewrap.cpp ----

// bwrap in PATH, and whether it can make its namespaces here (a container may forbid them).
struct BubblewrapProbe {
    std::filesystem::path program; // empty: not installed
    bool works = false;
};

// Looked up once.
const BubblewrapProbe& bubblewrapProbe();

// bwrap, when it can confine agents here.
std::filesystem::path bubblewrap();

// bwrap, its namespaces, and the system read-only (/usr, /lib..., the dynamic linker's files), its own
// /dev and /tmp: what every confined program sees (an agent, the compiler). /tmp is a tmpfs, or the
// folder `tmp` when given (an agent's: on disk, in its scratch folder, so that it counts against its
// disk limit; a tmpfs takes the machine's memory and bubblewrap 0.8 cannot size one).
std::vector<std::string> bubblewrapSystem(const std::filesystem::path& bwrap, const std::filesystem::path& tmp = {});

// The folder an agent sees as /tmp under bubblewrap, inside its scratch folder (made by the parent).
std::filesystem::path agentTmp(const std::filesystem::path& scratch);

// bwrap's arguments before an agent: the system read-only, the given files, nothing else.
std::vector<std::string> bubblewrapArgs(const std::filesystem::path& bwrap, const AgentCommand& c);

// ---- child_setup.cpp ----

// Everything the child needs, prepared before fork (after it, only async-signal-safe calls).
struct ChildPlan {
    std::vector<std::string> argv, env;
    std::vector<char*> cargv, cenv;
    std::filesystem::path scratch;
    SandboxLimits limits;
    int reportFd = -1, requestFd = -1;
    const UnprivilegedUser* user = nullptr;        // the fallback: the child becomes this user
    const std::vector<sock_filter>* seccomp = nullptr; // and installs this filter before exec
    const std::vector<std::string>* cgroup = nullptr;  // the run's cgroup it joins first (cgroup.h)
    int landlock = -1;                                 // and puts this Landlock ruleset in force (landlock.h)

    void seal() {
        for (std::string& a : argv) cargv.push_back(a.data());
        cargv.push_back(nullptr);
        for (std::string& e : env) cenv.push_back(e.data());
        cenv.push_back(nullptr);
    }
};

// In the forked child: its session, its cgroup, its user (the fallback), channels, limits, filter, then the program.
[[noreturn]] void execChild(const ChildPlan& plan);

// A small environment: the grader's variables are none of the child's business.
std::vector<std::string> childEnvironment(const AgentCommand& c, const SandboxLimits& limits);

// ---- child_guard.cpp ----

// While an agent runs, the grader adopts (as a subreaper) the processes it leaves, so that the
// sweep finds them, even bubblewrap's init once bubblewrap has gone. Without a PID namespace it
// also takes the signals the agent could send it.
class ChildGuard {
public:
    // Before the fork: from its first instruction, the child is guarded against.
    explicit ChildGuard(bool guardSignals);
    // Once the agent's tree is gone: the grader's own handlers are back, and a handler another thread
    // is still in has found this agent (a signal sent before its end) and recorded what it did.
    void stopGuarding();
    ~ChildGuard();
    void started(long agent);

    // What the agent tried (also while it was starting), taken from the shared record.
    std::vector<std::string> violations() const;

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
void sweep(long agent);

} // namespace raylab::grader::detail

#endif
