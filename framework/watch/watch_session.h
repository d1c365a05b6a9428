#pragma once
// One run of `raylab watch N`: at each save, lab N's grading agent is rebuilt, the lab is graded
// through it as `raylab grade --lab N` grades it (the same sandbox, checks, pictures and hints), and
// what the page shows is published: the pictures (student, reference, difference) in the watch's
// folder, the checks, the compiler's errors with their file and line, the problems (a crash as the
// grader says it: the figure that crashed, the checks that crashed, named after their function).

#include "watch/page_state.h"

#include <filesystem>
#include <mutex>
#include <string>
#include <vector>

namespace raylab::watch {

struct WatchSettings {
    int lab = 0;
    std::filesystem::path out;        // the page's files (out/watch): nothing outside it is served
    std::filesystem::path sourceDir;  // the tree
    std::filesystem::path buildDir;   // its build (`cmake --build` it)
    std::filesystem::path binDir;     // where its agents are
    std::string cmake, buildType;     // the cmake program, the build's configuration
    std::vector<std::filesystem::path> references; // the grader's references, each lab's folder
    std::filesystem::path labs;       // the lab descriptions (labs/)
    std::filesystem::path scenes;     // a folder of the figures' scene files; empty: each lab's
    int threads = 0;
};

class WatchSession {
public:
    // `agents`: held while the agent is built and graded (the pixel inspector runs it too).
    WatchSession(WatchSettings settings, PageState& page, std::mutex& agents);

    // Builds, grades and publishes; `changed`: the saved files that asked for it (empty: the first run).
    void refresh(const std::vector<std::filesystem::path>& changed);

    // Shows `problem` on the page in place of the grade (what stopped a refresh), the watch going on.
    void showProblem(const std::string& problem);

    const WatchSettings& settings() const { return m_settings; }

private:
    // Builds the lab's agent; empty when it built, else the compiler's output.
    std::string buildAgent();
    void publish(const std::string& phase, const std::vector<std::filesystem::path>& changed);

    WatchSettings m_settings;
    PageState& m_page;
    std::mutex& m_agents;
    std::string m_graded = "{}";   // the last grade's figures, checks and labs, as JSON members
    std::string m_buildOutput;     // the last failed build's output; empty when it built
    double m_buildSeconds = 0., m_gradeSeconds = 0.;
};

} // namespace raylab::watch
