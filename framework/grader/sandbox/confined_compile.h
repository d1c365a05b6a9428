#pragma once
// The compiler of a submission's file under bubblewrap (raylab-build-guard, build_guard.cpp): it sees
// the system read-only, the folders it was allowed read-only (the submission's copy, the stubs, the
// include folders) and a private folder of its own, where it writes the object and dependency files
// that the guard then moves to where the build expects them. A path it was not given does not exist
// for it, so `#include`, `#embed` and the assembler's `.incbin` of any other file fail, whatever the
// path; and the other objects of the build folder (a classmate's, in a class run) are not there.

#include "grader/sandbox/compile_stage.h"
#include "grader/sandbox/landlock.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace raylab::grader {

namespace detail {
struct UnprivilegedUser;
}

// Without bubblewrap, as root (the fallback, unprivileged.h), the compiler runs as an unprivileged
// user instead, on copies of the folders it was allowed (compile_stage.h: wherever the tree is, that
// user reaches them), and writes only its private folder there (handed to that user, its temporary
// folder too), from where the guard moves the outputs, back in root's hands; where the kernel has
// Landlock (landlock.h) it may open only the system, those copies and its private folder, so that
// `.incbin` of another file fails there too. Without Landlock it reads every world-readable file.
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

    // [bwrap ... --] the command, its -o and -MF pointing into the private folder (the fallback: its
    // paths of allowed files pointing to their copies).
    const std::vector<std::string>& command() const { return m_command; }

    // The fallback's copies, whose paths the compiler's words must be given back; null otherwise.
    detail::CompileStage* stage() { return m_stage ? &*m_stage : nullptr; }

    // After a compile that succeeded: each output moved to its place (the fallback: read as a file the
    // user wrote, the dependency file with the original paths). False when one is missing or refused.
    bool deliver() const;

    // What the compiler may open under the fallback's Landlock: the system, the folders it may read,
    // the programs of the command outside /usr, its private folder.
    const detail::LandlockRules& landlockRules() const { return m_rules; }
    const std::filesystem::path& privateFolder() const { return m_private; }

private:
    struct Output {
        std::filesystem::path file, place; // in the private folder, where the build expects it
        bool dependencies = false;         // the dependency file (-MF)
    };
    std::optional<detail::CompileStage> m_stage; // the fallback's
    std::vector<std::string> m_command;
    std::filesystem::path m_private; // empty when the command names no output
    bool m_handedOver = false;       // the private folder belongs to the fallback's user
    std::vector<Output> m_outputs;
    detail::LandlockRules m_rules;
};

} // namespace raylab::grader
