#pragma once
// The sandbox where bubblewrap cannot start (not installed, or a container such as Gradescope's that
// forbids namespaces) and the grader runs as root: the compiler and the agents run as an unprivileged
// user, in a folder only that user can write, under a seccomp filter and, where the kernel has it,
// Landlock (landlock.h). An agent runs from a copy of its program, beside copies of its inputs, in a
// folder of the grader's that user may read (AgentStage): no other program of the build, wherever the
// tree is (under /root, read-only). docs/grading.md says what that promises. POSIX only; the build
// guard uses it too (no message catalogue here).

#include <filesystem>
#include <optional>
#include <string>
#include <sys/types.h>
#include <vector>

struct sock_filter;

namespace raylab::grader::detail {

// How a program of the student's is confined: bubblewrap's namespaces, an unprivileged user (root
// without bubblewrap), or only its own process group (not root, or turned off).
enum class SandboxMode { bubblewrap, unprivileged, processGroup };

// RAYLAB_SANDBOX=bubblewrap|fallback|none forces a mode (a test runs the fallback on a machine that
// has bubblewrap; `--no-sandbox` sets none for the compiler it starts); otherwise, or when the mode
// asked for cannot run here, the best this machine has. `allowed` false: none (`--no-sandbox`).
SandboxMode sandboxMode(bool allowed = true);

// The user the fallback runs programs as: `raylab-grader` (setup.sh creates it), else `nobody`.
struct UnprivilegedUser {
    uid_t uid = 0;
    gid_t gid = 0;
    std::string name;
};

// Looked up once (not after a fork: the lookup is not async-signal-safe); empty when not root or
// when neither user exists.
const std::optional<UnprivilegedUser>& unprivilegedUser();

// `folder` belongs to `user`, mode 0700: only it writes there, and no other unprivileged program
// reads it. False when it cannot be done.
bool handOver(const std::filesystem::path& folder, const UnprivilegedUser& user);

// A folder of root's made by mkdtemp from `pattern` (its name ends in XXXXXX), then mode 0711: others
// may enter it, not list it. Throws when it cannot be made.
std::filesystem::path makeEnterableFolder(const std::filesystem::path& pattern);

// `from`, a file or a folder with its files and folders, copied to `to`, root's, readable by anyone and
// writable by no one (folders 0555, files 0444); links and special files are left out, never followed.
// Throws when a copy fails.
void copyReadOnly(const std::filesystem::path& from, const std::filesystem::path& to);

// An agent's program and inputs copied where the fallback's user can read them and nothing beside:
// /tmp/raylab-agent-XXXXXX/, root's, mode 0711 (entered, never listed); the program 0555, the inputs
// 0444 (their folders 0555), links left out. Removed when it goes.
class AgentStage {
public:
    AgentStage(const std::filesystem::path& program, const std::vector<std::filesystem::path>& readable);
    ~AgentStage();
    AgentStage(const AgentStage&) = delete;
    AgentStage& operator=(const AgentStage&) = delete;

    const std::filesystem::path& program() const { return m_program; }
    const std::vector<std::filesystem::path>& readable() const { return m_readable; } // the copies, in order

    // `requests` with each input's path, where a JSON string names it or a file in it, renamed to its copy's.
    std::string renamed(std::string requests) const;

private:
    std::filesystem::path m_folder, m_program;
    std::vector<std::filesystem::path> m_given, m_readable;
};

// In the forked child (async-signal-safe): no supplementary groups, the user's group, then the user;
// true only once root cannot be taken back (setuid(0) fails).
bool dropPrivileges(const UnprivilegedUser& user);

// Whether raylab was built with libseccomp: without it the fallback has no seccomp filter.
bool haveSeccomp();

// The seccomp filter's program, compiled once before any fork: sockets other than AF_UNIX, ptrace,
// process_vm_readv/writev and io_uring (which opens sockets without the socket call) fail. Empty when
// raylab was built without libseccomp; throws when libseccomp cannot compile it (nothing runs unfiltered).
const std::vector<sock_filter>& seccompProgram();

// In the forked child, last before exec (async-signal-safe): no new privileges, then the filter.
// True when it is in place, or when there is none to install.
bool installSeccomp(const std::vector<sock_filter>& program);

} // namespace raylab::grader::detail
