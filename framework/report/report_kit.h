#pragma once
// raylab report: the student's lab report kit. Renders this build's figures, grades the code as
// `raylab grade` does (the same agents, the same total), and writes DIR/report.md (the student's
// document: a re-run keeps their text) and DIR/report.html (every image beside it in DIR), and
// DIR/report.pdf when asked and chromium is installed.

#include <filesystem>
#include <string>
#include <vector>

namespace raylab::report {

struct ReportRequest {
    std::filesystem::path out;        // the kit's folder
    std::filesystem::path treeOut;    // the tree's out/: report.html shows images from there and the kit alone
    std::string lang = "en";          // "en" or "fr"
    bool pdf = false;                 // also print report.pdf
    int threads = 0;                  // 0: one per core
    bool progress = false;            // progress bars on a terminal
    bool referenceBuild = false;      // this program was built from solutions/: grade the reference agent
    std::filesystem::path scenes;     // the figures' scene files
    std::vector<std::filesystem::path> references; // the grader's reference folders
    std::filesystem::path labs;       // the labs' descriptions
    std::filesystem::path programs;   // where the agents are (beside raylab)
    std::vector<int> unbuilt;         // the labs whose code did not compile (their agents left out)
    std::string buildMessage;         // what the compiler said of them
};

// Writes the kit; returns the exit status (0, or 1 when --pdf was asked and no PDF could be made).
int writeReportKit(const ReportRequest& request);

} // namespace raylab::report
