#pragma once
// Similar submissions, for a person to look at, never a penalty: per lab, the pairs of students whose
// lab files share the most code once the stub's own lines are removed (what MOSS calls base code), and
// the lines most of the class wrote alike (as MOSS ignores passages found in many programs), measured
// by Debian's similarity-tester (`sim_c++`: token runs that survive renaming and layout); each pair's
// overlap set against the class's usual overlap for that lab.

#include "grader/class_page/class_results.h"
#include "grader/lab_catalog.h"

#include <filesystem>
#include <string>
#include <vector>

namespace raylab::grader {

// Lines of each side's text (from 1) that sim_c++ found alike, and how many tokens they hold.
struct MatchedRun {
    int firstFrom = 0, firstTo = 0, secondFrom = 0, secondTo = 0;
    int tokens = 0;
};

struct SimilarPair {
    std::size_t first = 0, second = 0; // in LabSimilarity::students
    int overlap = 0;                    // percent of either side's own code found in the other (the larger)
    bool unusual = false;               // above the class's upper fence for this lab
    std::vector<MatchedRun> runs;
};

struct LabSimilarity {
    int lab = 0;
    std::vector<std::string> students;  // those with code of their own in this lab
    std::vector<std::string> texts;     // each one's lab files, joined, as shown
    std::vector<std::vector<bool>> leftOut;   // per text: whether a line (from 0) was left out (the stub's, or common)
    std::vector<SimilarPair> pairs;     // the most similar first, at most kShownPairs
    double median = 0.;                 // the usual overlap of two students of the class, percent
    double fence = 0.;                  // Tukey's upper fence of the overlaps (Q3 + 1.5 IQR): above it, unusual
    std::size_t comparedPairs = 0;
};

inline constexpr std::size_t kShownPairs = 10;

struct SimilarityReport {
    std::vector<LabSimilarity> labs;
    std::string note; // why there is none (sim_c++ not installed, or it failed), in the reader's language
};

// The students' copies (OUT/students/<safe>/submission/<lab id>/<file>) against the stubs of
// `labsFolder`; `scratch` holds the files compared. A lab where fewer than two students wrote code
// has no pairs.
SimilarityReport findSimilarSubmissions(const ClassResults& results, const LabCatalog& labs,
                                        const std::filesystem::path& labsFolder, const std::filesystem::path& scratch);

} // namespace raylab::grader
