// Landlock through its raw system calls (<linux/landlock.h>; glibc has no wrapper): the ABI the
// kernel has, a ruleset made before fork, put in force in the child.
#include "grader/sandbox/landlock.h"

#include "grader/sandbox/sandbox_internal.h"

#ifdef RAYLAB_POSIX_SANDBOX

#include <cerrno>
#include <cstdint>
#include <iterator>
#include <stdexcept>
#include <string>
#include <unistd.h>
#if defined(__linux__) && __has_include(<linux/landlock.h>)
#include <fcntl.h>
#include <linux/landlock.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#endif

namespace raylab::grader::detail {

namespace fs = std::filesystem;

// Linux with Landlock's header (5.13 and later) and a C library that numbers its calls (glibc 2.34).
#if defined(LANDLOCK_CREATE_RULESET_VERSION) && defined(SYS_landlock_create_ruleset)

namespace {

// The rights of later ABIs, by their numbers in the kernel's ABI, for headers older than the kernel
// (Debian 12's stops at ABI 2, Ubuntu 22.04's at ABI 1).
constexpr std::uint64_t kRefer = 1ull << 13;    // ABI 2
constexpr std::uint64_t kTruncate = 1ull << 14; // ABI 3
constexpr std::uint64_t kIoctlDev = 1ull << 15; // ABI 5
constexpr std::uint64_t kNetBindTcp = 1ull << 0, kNetConnectTcp = 1ull << 1; // ABI 4
constexpr std::uint64_t kScopeAbstractUnixSocket = 1ull << 0, kScopeSignal = 1ull << 1; // ABI 6

// The ruleset's attributes as ABI 6 lays them out; an older kernel is given the part it knows.
struct RulesetAttributes {
    std::uint64_t handledFs = 0, handledNet = 0, scoped = 0;
};

constexpr std::uint64_t kRead = LANDLOCK_ACCESS_FS_READ_FILE | LANDLOCK_ACCESS_FS_READ_DIR;
constexpr std::uint64_t kFileRights = LANDLOCK_ACCESS_FS_EXECUTE | LANDLOCK_ACCESS_FS_WRITE_FILE |
                                      LANDLOCK_ACCESS_FS_READ_FILE | kTruncate | kIoctlDev;

// Every file-system right this kernel knows: all are handled, so what no rule allows is refused.
std::uint64_t handledFs(int abi) {
    std::uint64_t rights = (LANDLOCK_ACCESS_FS_MAKE_SYM << 1) - 1; // ABI 1: bits 0 to 12
    if (abi >= 2) rights |= kRefer;
    if (abi >= 3) rights |= kTruncate;
    if (abi >= 5) rights |= kIoctlDev;
    return rights;
}

void addRule(int ruleset, const fs::path& path, std::uint64_t access) {
    const int fd = open(path.c_str(), O_PATH | O_CLOEXEC);
    if (fd < 0) {
        if (errno == ENOENT || errno == ENOTDIR) return; // not on this machine
        throw std::runtime_error("grader: Landlock cannot open " + path.string());
    }
    struct stat st {};
    const bool folder = fstat(fd, &st) == 0 && S_ISDIR(st.st_mode);
    landlock_path_beneath_attr rule{folder ? access : access & kFileRights, fd};
    const long added = syscall(SYS_landlock_add_rule, ruleset, LANDLOCK_RULE_PATH_BENEATH, &rule, 0);
    close(fd);
    if (added != 0) throw std::runtime_error("grader: Landlock refuses the rule for " + path.string());
}

} // namespace

int landlockAbi() {
    static const int abi = [] {
        const long version = syscall(SYS_landlock_create_ruleset, nullptr, 0, LANDLOCK_CREATE_RULESET_VERSION);
        return version > 0 ? int(version) : 0;
    }();
    return abi;
}

LandlockRuleset::LandlockRuleset(const LandlockRules& rules) {
    const int abi = landlockAbi();
    if (abi == 0) return;
    RulesetAttributes attributes{handledFs(abi), 0, 0};
    std::size_t size = sizeof attributes.handledFs;
    if (abi >= 4) { // no TCP at all (the seccomp filter refuses every socket but AF_UNIX too)
        attributes.handledNet = kNetBindTcp | kNetConnectTcp;
        size += sizeof attributes.handledNet;
    }
    if (abi >= 6) { // no signal to, and no abstract socket of, a process outside the sandbox
        attributes.scoped = kScopeAbstractUnixSocket | kScopeSignal;
        size += sizeof attributes.scoped;
    }
    m_fd = int(syscall(SYS_landlock_create_ruleset, &attributes, size, 0));
    if (m_fd < 0) throw std::runtime_error("grader: Landlock cannot make a ruleset");
    fcntl(m_fd, F_SETFD, FD_CLOEXEC);
    const std::uint64_t all = attributes.handledFs;
    try {
        for (const fs::path& path : rules.execute) addRule(m_fd, path, kRead | LANDLOCK_ACCESS_FS_EXECUTE);
        for (const fs::path& path : rules.read) addRule(m_fd, path, kRead);
        for (const fs::path& path : rules.readWrite) addRule(m_fd, path, all & ~std::uint64_t(LANDLOCK_ACCESS_FS_EXECUTE));
    } catch (...) {
        close(m_fd);
        throw;
    }
}

LandlockRuleset::~LandlockRuleset() {
    if (m_fd >= 0) close(m_fd);
}

bool restrictSelf(int rulesetFd) {
    if (rulesetFd < 0) return true;
    return prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) == 0 && syscall(SYS_landlock_restrict_self, rulesetFd, 0) == 0;
}

#else

int landlockAbi() { return 0; }

LandlockRuleset::LandlockRuleset(const LandlockRules&) {}

LandlockRuleset::~LandlockRuleset() = default;

bool restrictSelf(int rulesetFd) { return rulesetFd < 0; }

#endif

LandlockRules systemRules() {
    LandlockRules rules;
    rules.execute.assign(std::begin(kSystemTopFolders), std::end(kSystemTopFolders));
    rules.execute.emplace_back("/usr");
    rules.read.assign(std::begin(kSystemEtcFiles), std::end(kSystemEtcFiles));
    for (const char* path : {"/dev/urandom", "/dev/random", "/dev/zero", "/sys/devices/system/cpu"}) rules.read.emplace_back(path);
    rules.readWrite.emplace_back("/dev/null");
    return rules;
}

} // namespace raylab::grader::detail

#endif
