#pragma once
// The compiler of a submission's file under bubblewrap (raylab-build-guard, build_guard.cpp): it sees
// the system read-only, the folders it was allowed read-only (the submission's copy, the stubs, the
// include folders) and a private folder of its own, where it writes the object and dependency files
// that the guard then moves to where the build expects them. A path it was not given does not exist
// for it, so `#include`, `#embed` and the assembler's `.incbin` of any other file fail, whatever the
// path; and the other objects of the build folder (a classmate's, in a class run) are not there.

#include "grader/sandbox/landlock.h"

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace raylab::grader {

namespace detail {
struct UnprivilegedUser;
}

// Without bubblewrap, as root (the fallback, unprivileged.h), the compiler runs as an unprivileged
// user instead, and writes only its private folder (handed to that user, its temporary folder too),
// from where the guard moves the outputs, back in root's hands; where the kernel has Landlock
// (landlock.h) it may open only the system, the folders it was allowed and its private folder, so
// that `.incbin` of another file fails there too. Without Landlock it reads every world-readable file.
class ConfinedCompile {
public:
    // `compiler`: the command (a launcher, the compiler and its arguments); `readable`: the folders it
    // may read; `bwrap` empty: no namespaces, the command as it is (the fallback, `user` given).
    // Makes the private folder beside the object file.
    ConfinedCompile(const std::filesystem::path& bwrap, const std::vector<std::string>& compiler,
                    const std::vector<std::filesystem::path>& readable, const detail::UnprivilegedUser* user = nullptr);
    ~ConfinedCompile(); // removes the private folder
    ConfinedCompile(const ConfinedCompile&) = delete;
    ConfinedCompile& operator=(const ConfinedCompile&) = delete;

    // [bwrap ... --] the command, its -o and -MF pointing into the private folder.
    const std::vector<std::string>& command() const { return m_command; }

    // After a compile that succeeded: each output moved to its place. False when one is missing.
    bool deliver() const;

    // What the compiler may open under the fallback's Landlock: the system, the folders it may read,
    // the programs of the command outside /usr, its private folder.
    const detail::LandlockRules& landlockRules() const { return m_rules; }
    const std::filesystem::path& privateFolder() const { return m_private; }

private:
    std::vector<std::string> m_command;
    std::filesystem::path m_private; // empty when the command names no output
    bool m_handedOver = false;       // the private folder belongs to the fallback's user
    std::vector<std::pair<std::filesystem::path, std::filesystem::path>> m_outputs; // private file, its place
    detail::LandlockRules m_rules;
};

} // namespace raylab::grader
