#pragma once
// Landlock (Linux 5.13 and later): an unprivileged process restricts, for itself and everything it
// starts, which files it may open, by path, without namespaces. The fallback sandbox (unprivileged.h)
// puts an agent and the student's compiler under it: the system's folders to read and run, their
// inputs to read, their own folder to write, nothing else of the machine (not the build's other
// programs, not solutions/, not a classmate's folder). POSIX only; no message catalogue here.

#include <filesystem>
#include <vector>

namespace raylab::grader::detail {

// What a program may reach; a path missing on this machine is left out.
struct LandlockRules {
    std::vector<std::filesystem::path> execute;   // read and run (the system's folders, its own program)
    std::vector<std::filesystem::path> read;      // read (its inputs)
    std::vector<std::filesystem::path> readWrite; // read, write, create and remove (its scratch folder)
};

// The kernel's Landlock ABI version (1, 2 ...), 0 without Landlock (an older kernel, turned off, not Linux).
int landlockAbi();

// The system's folders that a dynamically linked program and the compiler read and run, as bubblewrap
// shows them: /usr, /lib*, /bin, /sbin, of /etc the dynamic loader's files and the alternatives; the
// devices a program opens (/dev/null, /dev/urandom) and the CPU count in /sys.
LandlockRules systemRules();

// A ruleset made before fork (paths are opened, memory allocated), to be put in force in the child.
// Without Landlock it holds nothing; throws when the kernel has Landlock and refuses a rule (nothing
// runs less confined than the results say).
class LandlockRuleset {
public:
    explicit LandlockRuleset(const LandlockRules& rules);
    ~LandlockRuleset();
    LandlockRuleset(const LandlockRuleset&) = delete;
    LandlockRuleset& operator=(const LandlockRuleset&) = delete;

    int fd() const { return m_fd; } // -1 without Landlock

private:
    int m_fd = -1;
};

// In the forked child (async-signal-safe): no new privileges, then the ruleset in force for good.
// True when it is, or when there is none (fd -1).
bool restrictSelf(int rulesetFd);

} // namespace raylab::grader::detail
