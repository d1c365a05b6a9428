// raylab-build-guard: the compiler launcher of a submission's lab files (POSIX; see
// framework/grader/CMakeLists.txt). A submission is code we compile before any sandbox runs it, so
// the compiler is where it can reach what it must not:
//  - `#include "raylab/../../../solutions/<lab>/<file>.cpp"`, `#embed` or the
//    assembler's `.incbin` of a solution (or a classmate's file) would grade the reference as the
//    student's work, or throw its bytes into the report: on Linux with bubblewrap the compiler runs
//    confined (confined_compile.h), seeing only the allowed folders (the submission, the stubs, the
//    include folders of the command line) and the system; where bubblewrap cannot start and we are
//    root, it runs as an unprivileged user on copies of the allowed folders (compile_stage.h: so
//    wherever the tree is; its words and dependency file get the original paths back), writes only its
//    private folder and, where the kernel has Landlock, opens only the system, those copies and that folder; without
//    Landlock it reads every world-readable file); RAYLAB_SANDBOX=none|fallback in the environment chooses (see
//    sandboxMode). Then, a second wall, every file the compiler read must lie in an allowed folder
//    or the compiler's own, checked on the dependency file it writes, after symlinks (`.incbin` is
//    not in it: only the sandbox stops that);
//  - `#include "/dev/zero"` or a template that never ends would stall a class run: the compiler runs
//    under CPU, memory and file-size limits and a wall-clock limit, in a process group of its own
//    that is killed whole; and within the whole build's time, when the grader gives it
//    (RAYLAB_BUILD_DEADLINE in the environment: seconds since the epoch), so that a constexpr bomb in
//    each lab file costs one build's time, not each file's.
// Usage: raylab-build-guard [--allow DIR]... [--wall-seconds N] -- COMPILER ARGS...
// A refusal is one line `raylab-build-guard: <why>: <source>[ <- <file read>]` on stderr, <why> one of `outside`,
// `time` (past the CPU or wall-clock limit), `build-time` (the build's deadline passed), `killed` (by a
// signal from elsewhere: out of memory), `no-depfile` (the grader says it in the student's language,
// grader/submission.cpp), and exit status 1, with the object file removed; so is the object of a
// compile that failed (one stopped at the file size limit, kCompilerFileBytes, would stay in a build
// folder a class shares).
#include "grader/sandbox/build_limits.h"
#include "grader/sandbox/confined_compile.h"
#include "grader/sandbox/landlock.h"
#include "grader/sandbox/sandbox_internal.h"
#include "grader/sandbox/scratch_file.h"
#include "grader/sandbox/unprivileged.h"

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <fcntl.h>
#include <string_view>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#ifdef __linux__
#include <sys/prctl.h>
#endif

namespace fs = std::filesystem;

namespace {

// A lab file compiles in a few seconds; these are far beyond any honest one.
constexpr rlim_t kCpuSeconds = 120;
constexpr unsigned kWallSeconds = 300; // --wall-seconds N (the tests)
constexpr rlim_t kMemoryBytes = rlim_t(2) << 30;
constexpr std::size_t kDepfileBytes = std::size_t(16) << 20; // a lab file's lists a few hundred headers

volatile std::sig_atomic_t g_compiler = 0; // the compiler's process group, once started
volatile std::sig_atomic_t g_timedOut = 0;

extern "C" void onAlarm(int) {
    g_timedOut = 1;
    if (g_compiler > 0) kill(-pid_t(g_compiler), SIGKILL);
}

// Ctrl-C or a stop reaches us (we are in the build's process group), not the compiler's group.
extern "C" void onStop(int signal) {
    if (g_compiler > 0) kill(-pid_t(g_compiler), SIGKILL);
    std::signal(signal, SIG_DFL);
    raise(signal);
}

int refuse(const char* why, const std::string& source, const std::string& object, const std::string& read = "") {
    std::fprintf(stderr, "raylab-build-guard: %s: %s%s%s\n", why, source.c_str(), read.empty() ? "" : " <- ", read.c_str());
    std::error_code ignored;
    if (!object.empty()) fs::remove(object, ignored);
    return 1;
}

struct Command {
    std::vector<fs::path> allowed;
    unsigned wallSeconds = kWallSeconds;
    std::vector<std::string> compiler; // the compiler and its arguments
    std::string object, depfile;       // -o and -MF, when given
};

std::optional<Command> parse(int argc, char** argv) {
    Command c;
    int k = 1;
    for (; k < argc && std::strcmp(argv[k], "--") != 0; ++k) {
        if (k + 1 >= argc) return std::nullopt;
        if (std::strcmp(argv[k], "--allow") == 0) c.allowed.emplace_back(argv[++k]);
        else if (std::strcmp(argv[k], "--wall-seconds") == 0) c.wallSeconds = unsigned(std::atoi(argv[++k]));
        else return std::nullopt;
    }
    if (c.wallSeconds == 0) return std::nullopt;
    if (k + 1 >= argc) return std::nullopt;
    c.compiler.assign(argv + k + 1, argv + argc);
    // The include folders of the command line are allowed (CMake writes them; the submission cannot).
    const std::vector<std::string> includeFlags{"-I", "-isystem", "-iquote", "-idirafter"};
    for (std::size_t i = 1; i < c.compiler.size(); ++i) {
        const std::string& a = c.compiler[i];
        const bool hasNext = i + 1 < c.compiler.size();
        if (a == "-o" && hasNext) c.object = c.compiler[i + 1];
        if (a == "-MF" && hasNext) c.depfile = c.compiler[i + 1];
        for (const std::string& flag : includeFlags) {
            if (a == flag && hasNext) c.allowed.emplace_back(c.compiler[i + 1]);
            else if (a.size() > flag.size() && a.compare(0, flag.size(), flag) == 0 && flag == "-I")
                c.allowed.emplace_back(a.substr(flag.size()));
        }
    }
    return c;
}

// The files a Make-style dependency file lists after its target: `obj: a.cpp b.h \` ...
std::vector<std::string> dependencies(const std::string& text) {
    std::vector<std::string> files;
    std::string word;
    bool pastTarget = false;
    const auto flush = [&] {
        if (word.empty()) return;
        if (pastTarget) files.push_back(word);
        else if (word.back() == ':') pastTarget = true;
        word.clear();
    };
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char ch = text[i];
        if (ch == '\\' && i + 1 < text.size() && (text[i + 1] == '\n' || text[i + 1] == '\r')) {
            flush();
            ++i;
        } else if (ch == '\\' && i + 1 < text.size() && (text[i + 1] == ' ' || text[i + 1] == '#')) {
            word += text[++i];
        } else if (ch == '$' && i + 1 < text.size() && text[i + 1] == '$') {
            word += text[++i];
        } else if (ch == ' ' || ch == '\t' || ch == '\n' || ch == '\r') {
            flush();
        } else {
            word += ch;
        }
    }
    flush();
    return files;
}

bool isWithin(const fs::path& file, const fs::path& folder) {
    const auto [end, _] = std::mismatch(folder.begin(), folder.end(), file.begin(), file.end());
    return end == folder.end();
}

fs::path resolved(const fs::path& path) {
    std::error_code error;
    const fs::path real = fs::weakly_canonical(fs::absolute(path), error);
    return error ? fs::absolute(path).lexically_normal() : real;
}

// What stopped a compiler that did not end by itself.
constexpr int kPastTimeLimit = -1, kKilled = -2;

// The compiler's error output passed on with the copies' paths put back (the fallback's stage), as
// it comes: it may be a gigabyte.
void passOnErrors(int from, raylab::grader::detail::CompileStage& stage) {
    std::vector<char> buffer(std::size_t(64) << 10);
    const auto write = [](const std::string& text) {
        for (std::size_t done = 0; done < text.size();) {
            const ssize_t n = ::write(STDERR_FILENO, text.data() + done, text.size() - done);
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) return;
            done += std::size_t(n);
        }
    };
    for (;;) {
        const ssize_t n = read(from, buffer.data(), buffer.size());
        if (n < 0 && errno == EINTR) continue; // the wall-clock alarm: the compiler is being killed
        if (n <= 0) break;
        write(stage.originalPart(std::string_view(buffer.data(), std::size_t(n))));
    }
    write(stage.originalPart({}, true));
}

// Runs the compiler under the limits (as `user`, under the seccomp filter, when given); its exit
// status, or kPastTimeLimit, or kKilled. With `stage`, its error output goes through passOnErrors.
int compile(const std::vector<std::string>& argv, unsigned wallSeconds,
            const raylab::grader::detail::UnprivilegedUser* user, int landlock,
            raylab::grader::detail::CompileStage* stage) {
    const std::vector<sock_filter>* filter = user ? &raylab::grader::detail::seccompProgram() : nullptr;
    // Made before fork: the child allocates nothing under its address-space limit (an ASan build's
    // allocator would fail there).
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    int errors[2] = {-1, -1};
    if (stage && pipe2(errors, O_CLOEXEC) != 0) return 127;
    const pid_t pid = fork();
    if (pid < 0) return 127;
    if (pid == 0) {
        setpgid(0, 0);
        if (stage && dup2(errors[1], STDERR_FILENO) < 0) _exit(127);
        if (user && !raylab::grader::detail::dropPrivileges(*user)) {
            std::fprintf(stderr, "error: raylab-build-guard cannot become the user %s\n", user->name.c_str());
            _exit(126);
        }
#ifdef __linux__
        prctl(PR_SET_PDEATHSIG, SIGKILL); // the driver dies with us (its compiler keeps the CPU limit)
#endif
        const rlim_t fileBytes = raylab::grader::kCompilerFileBytes;
        const rlimit cpu{kCpuSeconds, kCpuSeconds}, memory{kMemoryBytes, kMemoryBytes}, file{fileBytes, fileBytes};
        setrlimit(RLIMIT_CPU, &cpu);
        setrlimit(RLIMIT_AS, &memory);
        setrlimit(RLIMIT_FSIZE, &file);
        if (!raylab::grader::detail::restrictSelf(landlock)) _exit(126);
        if (filter && !raylab::grader::detail::installSeccomp(*filter)) _exit(126);
        execvp(args[0], args.data());
        std::fprintf(stderr, "error: raylab-build-guard cannot run %s: %s\n", args[0], std::strerror(errno));
        _exit(127);
    }
    setpgid(pid, pid);
    g_compiler = pid;
    alarm(wallSeconds);
    if (stage) {
        close(errors[1]);
        passOnErrors(errors[0], *stage);
        close(errors[0]);
    }
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    alarm(0);
    kill(-pid, SIGKILL); // whatever the driver left in its group
    if (g_timedOut || (WIFSIGNALED(status) && WTERMSIG(status) == SIGXCPU)) return kPastTimeLimit;
    if (WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) return kKilled;
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

// The file a refusal names: the source compiled (after -c), else the object, else the compiler.
std::string sourceOf(const Command& command) {
    std::string source = command.object.empty() ? command.compiler.front() : command.object;
    for (std::size_t i = 0; i + 1 < command.compiler.size(); ++i)
        if (command.compiler[i] == "-c") source = command.compiler[i + 1];
    return source;
}

// This file's wall-clock limit: its own, or what is left of the build's deadline (RAYLAB_BUILD_DEADLINE)
// when that comes first. Nothing when the deadline has passed.
struct WallLimit {
    unsigned seconds = 0;
    bool deadlineFirst = false;
};
std::optional<WallLimit> wallLimit(unsigned own) {
    WallLimit limit{own, false};
    if (const char* deadline = std::getenv("RAYLAB_BUILD_DEADLINE")) {
        const long long left = std::atoll(deadline) - static_cast<long long>(std::time(nullptr));
        if (left <= 0) return std::nullopt;
        limit.deadlineFirst = left < static_cast<long long>(own);
        if (limit.deadlineFirst) limit.seconds = unsigned(left);
    }
    return limit;
}

// The compiler's dependency file, read as any file an untrusted build wrote (not through a link, not
// past a cap): every file it names must be inside an allowed folder. 0, or the refusal's status.
int checkDependencies(const Command& command, const std::string& source) {
    if (command.depfile.empty()) return refuse("no-depfile", source, command.object);
    const raylab::grader::ScratchFile depfile = raylab::grader::readScratchFile(command.depfile, kDepfileBytes);
    if (!depfile.found || depfile.refused || depfile.cut) return refuse("no-depfile", source, command.object);
    std::vector<fs::path> allowed;
    for (const fs::path& folder : command.allowed) allowed.push_back(resolved(folder));
    // And the headers the system's packages keep in /usr/lib, which the include folders reach through
    // links: Debian 13's /usr/include/<triplet>/asm/*.h lead to /usr/lib/linux/uapi/, the name GCC 14
    // writes in the dependency file.
    allowed.emplace_back("/usr/lib");
    for (const std::string& file : dependencies(depfile.text)) {
        const fs::path real = resolved(file);
        const bool inside = std::any_of(allowed.begin(), allowed.end(), [&](const fs::path& f) { return isWithin(real, f); });
        if (!inside) return refuse("outside", source, command.object, real.string());
    }
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    const std::optional<Command> command = parse(argc, argv);
    if (!command) {
        std::fprintf(stderr, "usage: raylab-build-guard [--allow DIR]... [--wall-seconds N] -- COMPILER ARGS...\n");
        return 2;
    }
    struct sigaction alarmAction {};
    alarmAction.sa_handler = onAlarm; // no SA_RESTART: the wait returns
    sigaction(SIGALRM, &alarmAction, nullptr);
    for (int signal : {SIGINT, SIGTERM, SIGHUP}) std::signal(signal, onStop);

    const std::string source = sourceOf(*command);
    // Confined as the grader's agents are (RAYLAB_SANDBOX=none: not at all, `--no-sandbox`); the dependency
    // file is checked in every case, a second wall.
    using raylab::grader::detail::SandboxMode;
    const SandboxMode mode = raylab::grader::detail::sandboxMode();
    const fs::path bwrap = mode == SandboxMode::bubblewrap ? raylab::grader::detail::bubblewrap() : fs::path();
    const raylab::grader::detail::UnprivilegedUser* user =
        mode == SandboxMode::unprivileged ? &*raylab::grader::detail::unprivilegedUser() : nullptr;
    std::optional<raylab::grader::ConfinedCompile> confined;
    // The fallback's Landlock: the compiler opens the system, the allowed folders' copies and its own, nothing else.
    std::optional<raylab::grader::detail::LandlockRuleset> landlock;
    try {
        if (!bwrap.empty() || user) confined.emplace(bwrap, command->compiler, command->allowed, user);
        if (user) landlock.emplace(confined->landlockRules());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "error: raylab-build-guard: %s\n", e.what());
        return 1;
    }
    if (user) { // ccache, when it is the launcher, without its cache (root's, other builds' objects)
        setenv("CCACHE_DISABLE", "1", 1);
        setenv("CCACHE_DIR", "/nonexistent", 1); // its configuration is root's too
        setenv("TMPDIR", confined->privateFolder().c_str(), 1); // the compiler's temporary files, not the shared /tmp
    }
    const std::optional<WallLimit> limit = wallLimit(command->wallSeconds);
    if (!limit) return refuse("build-time", source, command->object);
    int status = compile(confined ? confined->command() : command->compiler, limit->seconds, user,
                         landlock ? landlock->fd() : -1, confined ? confined->stage() : nullptr);
    // bwrap passes a signal on as 128 + its number
    if (!bwrap.empty() && status == 128 + SIGXCPU) status = kPastTimeLimit;
    if (!bwrap.empty() && status == 128 + SIGKILL) status = g_timedOut ? kPastTimeLimit : kKilled;
    if (status == kPastTimeLimit)
        return refuse(limit->deadlineFirst && g_timedOut ? "build-time" : "time", source, command->object);
    if (status == kKilled) return refuse("killed", source, command->object);
    if (status != 0) {
        std::error_code ignored;
        if (!command->object.empty()) fs::remove(command->object, ignored);
        return status;
    }
    if (confined && !confined->deliver()) return refuse("no-depfile", source, command->object);
    return checkDependencies(*command, source);
}
