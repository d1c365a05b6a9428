#pragma once
// A run's scratch folder that outlives no run: `raylab-<what>-XXXXXX` in the temporary folder, its
// mark (`.raylab-run`) locked with flock while its run lives, removed at its end. A run killed with
// SIGKILL cannot remove its own, so each new run removes the `raylab-<what>-*` folders whose mark no
// live process holds (the kernel drops a flock with the last descriptor of its holder). A folder
// without the mark is never touched.

#include <filesystem>
#include <string>
#include <vector>

namespace raylab::grader {

class RunScratch {
public:
    // Removes the folders dead runs left, then makes and locks this run's own.
    explicit RunScratch(const std::string& what);
    ~RunScratch(); // removes the folder
    RunScratch(const RunScratch&) = delete;
    RunScratch& operator=(const RunScratch&) = delete;

    const std::filesystem::path& path() const { return m_path; }
    // The descriptor that holds the lock: a process forked from the run closes it, so that the lock
    // dies with the run itself.
    int lockDescriptor() const { return m_descriptor; }
    // The folders of dead runs this one removed when it started.
    const std::vector<std::filesystem::path>& removedAtStart() const { return m_removed; }

private:
    std::filesystem::path m_path;
    std::vector<std::filesystem::path> m_removed;
    int m_descriptor = -1; // holds the lock
};

// Removes `folder`'s `raylab-<what>-*` folders whose mark is ours (same owner) and held by no live
// run; returns them.
std::vector<std::filesystem::path> removeAbandonedScratch(const std::filesystem::path& folder, const std::string& what);

} // namespace raylab::grader
