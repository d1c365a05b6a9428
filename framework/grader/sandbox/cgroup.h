#pragma once
// One agent run's cgroup (Linux, as root, where the machine gives one: cgroup v2 with the pids and
// memory controllers enabled for the grader's own cgroup, or v1's pids and memory hierarchies): one
// limit on the processes and one on the memory of all of its processes together, bubblewrap's and the
// fallback's alike. Where there is none, the limits are those of each process (child_setup.cpp), as
// docs/grading.md says.

#include <string>
#include <vector>

namespace raylab::grader::detail {

class RunCgroup {
public:
    // Made for this run with these limits; inactive() when the machine gives none.
    RunCgroup(int processes, unsigned long long memoryBytes);
    ~RunCgroup(); // removed, once the run's processes are gone
    RunCgroup(const RunCgroup&) = delete;
    RunCgroup& operator=(const RunCgroup&) = delete;

    bool active() const { return !m_folders.empty(); }

    // The files the child writes "0" to, between fork and exec, to join (before anything it runs can fork).
    const std::vector<std::string>& joinFiles() const { return m_join; }

    // Whether a fork was refused at the process limit, or a process killed at the memory limit.
    bool processLimitHit() const;
    bool memoryLimitHit() const;

private:
    bool m_v2 = false;
    std::vector<std::string> m_folders; // v2: one; v1: the pids one, then the memory one
    std::vector<std::string> m_join;
};

// In the forked child (async-signal-safe): joins the run's cgroup; false when a file refused it.
bool joinCgroup(const std::vector<std::string>& joinFiles);

} // namespace raylab::grader::detail
