// The child's side of a run, between fork and exec: its session, user, channels, limits, filter and environment.
#include "grader/sandbox/sandbox_internal.h"

#include "grader/sandbox/landlock.h"

#ifdef RAYLAB_POSIX_SANDBOX

#include "grader/sandbox/cgroup.h"

#include <cstdlib>
#include <csignal>
#include <fcntl.h>
#include <sys/resource.h>
#include <unistd.h>
#ifdef __linux__
#include <sys/prctl.h>
#endif

namespace raylab::grader::detail {

namespace {

void limit(int resource, unsigned long long value) {
    rlimit r{rlim_t(value), rlim_t(value)};
    setrlimit(resource, &r);
}

} // namespace

[[noreturn]] void execChild(const ChildPlan& plan) {
    setsid(); // its own session and process group: the parent stops them all at once
    // Entered first: the fallback's user may not cross the grader's folders above it (a 0700 run scratch).
    if (chdir(plan.scratch.c_str()) != 0) _exit(126);
    // Its cgroup, joined while still root and before anything it runs can fork.
    if (plan.cgroup && !joinCgroup(*plan.cgroup)) _exit(126);
    // The fallback: never a student's program as root (126: it did not start).
    if (plan.user && !dropPrivileges(*plan.user)) _exit(126);
#ifdef __linux__
    prctl(PR_SET_PDEATHSIG, SIGKILL); // and it dies with the grader's thread that started it (after
                                      // the change of user, which clears it)
#endif
    const int out = open("stdout.txt", O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    const int err = open("stderr.txt", O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    const int null = open("/dev/null", O_RDONLY | O_CLOEXEC);
    // The channels, moved above the numbers they will take so that no dup2 overwrites the other.
    const int report = fcntl(plan.reportFd, F_DUPFD_CLOEXEC, 10);
    const int request = plan.requestFd >= 0 ? fcntl(plan.requestFd, F_DUPFD_CLOEXEC, 10) : -1;
    if (out < 0 || err < 0 || null < 0 || report < 0 || (plan.requestFd >= 0 && request < 0)) _exit(126);
    // Its files opened: from here it opens only what the fallback's Landlock rules allow.
    if (!restrictSelf(plan.landlock)) _exit(126);
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
    // Without a cgroup, the fallback's user's processes: counted for the user on the whole machine, and
    // never enforced for root (bubblewrap's agents), so the cgroup's limit comes first where there is one.
    if (plan.user && !plan.cgroup) limit(RLIMIT_NPROC, unsigned(plan.limits.processes));
    limit(RLIMIT_CORE, 0);
    if (plan.seccomp && !installSeccomp(*plan.seccomp)) _exit(126);
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

} // namespace raylab::grader::detail

#endif
