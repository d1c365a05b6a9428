#pragma once
// What the command line shows while it works.

#include <chrono>
#include <cstddef>

namespace raylab {

// True when standard error is an interactive terminal and not a CI job.
bool stderrIsInteractive();

// A one-line bar on standard error that appears only after a second of work, and only on a terminal.
class ProgressBar {
public:
    explicit ProgressBar(std::size_t total);
    void update(std::size_t done);
    void finish();

private:
    std::size_t m_total;
    bool m_shown = false;
    bool m_enabled;
    std::chrono::steady_clock::time_point m_start;
};

} // namespace raylab
