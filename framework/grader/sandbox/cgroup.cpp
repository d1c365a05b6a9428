#include "grader/sandbox/cgroup.h"

#include "grader/sandbox/sandbox_internal.h"
#include "src/atomic_file.h"

#ifdef RAYLAB_POSIX_SANDBOX

#include <atomic>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string_view>
#include <thread>
#include <unistd.h>

namespace raylab::grader::detail {

namespace fs = std::filesystem;

namespace {

constexpr const char* kRoot = "/sys/fs/cgroup";

bool writeFile(const fs::path& file, const std::string& text) {
    std::ofstream out(file);
    out << text;
    out.flush();
    return bool(out);
}

// A cgroup file's text; empty where it is absent (no cgroup, no such controller).
std::string readFile(const fs::path& file) { return readWholeFile(file).value_or(""); }

// The number after `key` in a flat keyed file ("max 3\n", "oom_kill 1\n"); 0 when absent.
long long keyed(const fs::path& file, const std::string& key) {
    std::istringstream in(readFile(file));
    std::string name;
    long long value = 0;
    while (in >> name >> value)
        if (name == key) return value;
    return 0;
}

// The grader's own cgroup v2 folder, when /sys/fs/cgroup is v2 and it delegates pids and memory to
// its children (cgroup.subtree_control); empty otherwise.
fs::path delegatingV2() {
    std::error_code error;
    if (!fs::exists(fs::path(kRoot) / "cgroup.controllers", error)) return {};
    std::istringstream lines(readFile("/proc/self/cgroup"));
    for (std::string line; std::getline(lines, line);)
        if (line.rfind("0::", 0) == 0) {
            const fs::path own = fs::path(kRoot) / fs::path(line.substr(3)).relative_path();
            std::istringstream enabled(readFile(own / "cgroup.subtree_control"));
            bool pids = false, memory = false;
            for (std::string controller; enabled >> controller;) {
                pids = pids || controller == "pids";
                memory = memory || controller == "memory";
            }
            if (pids && memory) return own;
        }
    return {};
}

constexpr const char* kPrefix = "raylab-run-";

std::string uniqueName() {
    static std::atomic<unsigned> count{0};
    return kPrefix + std::to_string(getpid()) + "-" + std::to_string(count++);
}

// The cgroups a grader killed with SIGKILL left in `parent` (raylab-run-<its pid>-N): removed once
// empty (rmdir refuses a cgroup that still holds a process).
void removeAbandoned(const fs::path& parent) {
    std::error_code error;
    for (fs::directory_iterator it(parent, error), end; !error && it != end; it.increment(error)) {
        const std::string name = it->path().filename().string();
        if (name.rfind(kPrefix, 0) != 0) continue;
        const long owner = std::atol(name.c_str() + std::string_view(kPrefix).size());
        if (owner > 0 && kill(pid_t(owner), 0) != 0 && errno == ESRCH) rmdir(it->path().c_str());
    }
}

} // namespace

RunCgroup::RunCgroup(int processes, unsigned long long memoryBytes) {
#ifdef __linux__
    if (geteuid() != 0) return;
    const std::string name = uniqueName(), pids = std::to_string(processes), memory = std::to_string(memoryBytes);
    std::error_code error;
    if (const fs::path parent = delegatingV2(); !parent.empty()) {
        removeAbandoned(parent);
        const fs::path folder = parent / name;
        if (!fs::create_directory(folder, error)) return;
        m_v2 = true;
        m_folders.push_back(folder.string());
        if (!writeFile(folder / "pids.max", pids) || !writeFile(folder / "memory.max", memory)) return;
        writeFile(folder / "memory.swap.max", "0"); // absent without swap accounting
        m_join.push_back((folder / "cgroup.procs").string());
        return;
    }
    const fs::path pidsFolder = fs::path(kRoot) / "pids" / name, memoryFolder = fs::path(kRoot) / "memory" / name;
    if (!fs::exists(pidsFolder.parent_path() / "cgroup.procs", error) ||
        !fs::exists(memoryFolder.parent_path() / "cgroup.procs", error))
        return;
    removeAbandoned(pidsFolder.parent_path());
    removeAbandoned(memoryFolder.parent_path());
    if (!fs::create_directory(pidsFolder, error)) return;
    m_folders.push_back(pidsFolder.string());
    if (!fs::create_directory(memoryFolder, error)) return;
    m_folders.push_back(memoryFolder.string());
    if (!writeFile(pidsFolder / "pids.max", pids) || !writeFile(memoryFolder / "memory.limit_in_bytes", memory)) return;
    writeFile(memoryFolder / "memory.memsw.limit_in_bytes", memory); // swap too, where it is accounted
    m_join = {(pidsFolder / "cgroup.procs").string(), (memoryFolder / "cgroup.procs").string()};
#else
    (void)processes;
    (void)memoryBytes;
#endif
}

RunCgroup::~RunCgroup() {
    // The sweep has killed and reaped every process; the kernel may take a moment to let them go.
    for (auto it = m_folders.rbegin(); it != m_folders.rend(); ++it)
        for (int attempt = 0; attempt < 100 && rmdir(it->c_str()) != 0 && errno == EBUSY; ++attempt)
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
}

bool RunCgroup::processLimitHit() const {
    return !m_join.empty() && keyed(fs::path(m_folders.front()) / "pids.events", "max") > 0;
}

bool RunCgroup::memoryLimitHit() const {
    if (m_join.empty()) return false;
    return m_v2 ? keyed(fs::path(m_folders.front()) / "memory.events", "oom_kill") > 0
                : keyed(fs::path(m_folders.back()) / "memory.oom_control", "oom_kill") > 0;
}

bool joinCgroup(const std::vector<std::string>& joinFiles) {
    for (const std::string& file : joinFiles) {
        const int fd = open(file.c_str(), O_WRONLY | O_CLOEXEC);
        const bool joined = fd >= 0 && write(fd, "0", 1) == 1;
        if (fd >= 0) close(fd);
        if (!joined) return false;
    }
    return true;
}

} // namespace raylab::grader::detail

#endif
