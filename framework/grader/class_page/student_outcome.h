#pragma once
// What the class page needs of one student's grade, kept beside their result in a class run
// (OUT/students/<safe name>/outcome.json): each lab's points, each check's and figure's verdict with
// the mistakes diagnosed in it, and the problems. The page is rebuilt from these files alone, never by
// grading again.

#include "grader/judge/outcome.h"

#include <filesystem>
#include <string>
#include <vector>

namespace raylab::grader {

struct ItemVerdict {
    bool figure = false; // else a function check
    int lab = 0;
    std::string name;    // the check's id as lab.toml writes it (shown by its title), or the figure's id
    bool passed = false;
    bool stopped = false;              // its run ended without its answer (a crash, a limit)
    std::vector<std::string> mistakes; // the catalogue's ids diagnosed in it
};

struct LabScore {
    int lab = 0;
    double points = 0., maxPoints = 0.;
    bool unbuilt = false; // its code did not compile
};

struct StudentOutcome {
    std::vector<LabScore> labs;
    std::vector<ItemVerdict> items;
    std::vector<std::string> problems; // each one's first lines (problemSummary)
    double points() const;
    double maxPoints() const;
};

StudentOutcome outcomeOf(const GradeResult& result);

// Written whole (atomically) or not at all.
void writeStudentOutcome(const StudentOutcome& outcome, const std::filesystem::path& file);

// Throws std::runtime_error naming the file and what is wrong with it.
StudentOutcome readStudentOutcome(const std::filesystem::path& file);

} // namespace raylab::grader
