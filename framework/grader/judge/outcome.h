#pragma once
// What a grade found: each check, figure and lab, their verdicts and points. Plain data, written by
// the judge and read by the reports, the class run and the autograders.

#include "grader/judge/compare.h"

#include <filesystem>
#include <string>
#include <vector>

namespace raylab::grader {

struct CheckOutcome {
    int lab = 0;
    std::string name; // the check's id (lab.toml); shown as its title, titleInLanguage(name)
    bool passed = false;
    std::string message; // expected / got / hint, or why it never ran
    double points = 0., maxPoints = 0.;
    int stubLab = 0; // the lab whose stub the check reached ("not done yet"); 0 when none
    bool stopped = false; // its run ended without its answer (a crash, a limit, an attack): the class page lists it
};

struct FigureOutcome {
    std::string id;
    int lab = 0;
    bool passed = false;
    bool found = true;   // --images: false when the file is missing (listed, not deciding the exit status)
    std::string reason;  // the verdict's line, or why there is no image
    ImageVerdict verdict;
    std::string diagnosis;              // the closest classic mistake, when one fits
    std::vector<std::string> mistakes;  // its id (and the one that draws the same picture): the class page counts them
    std::filesystem::path studentImage; // empty when there is none
    double points = 0., maxPoints = 0.;
    int stubLab = 0; // the lab whose stub its render reached; 0 when none
    bool stopped = false; // its run ended without its answer (a crash, a limit, an attack)
};

struct LabOutcome {
    int lab = 0;
    double points = 0., maxPoints = 0.;
    std::vector<std::string> notes; // "graded with the other labs from the reference", the labs to fix first
    bool notStarted = false;        // every item reached this lab's own stubs: nothing of it is written yet
    bool unbuilt = false;           // its code did not compile: every item at zero
};

struct GradeResult {
    std::string title;
    std::vector<CheckOutcome> checks;
    std::vector<FigureOutcome> figures;
    std::vector<LabOutcome> labs;
    std::vector<std::string> problems; // what went wrong around the items (a crash, a compile error)

    double score() const;
    double maxScore() const;
    bool allPassed() const; // every check and every figure found passed
};

} // namespace raylab::grader
