#pragma once
// The class page (OUT/index.html), in the instructor's language and offline: the scores' histograms
// per lab and in total, each check's and figure's pass rate from the least passed, the diagnosed
// mistakes with how many students made each, the students whose code did not build or stopped, the
// similar submissions (with a side-by-side page per pair, OUT/similarity/) and a link to each
// student's report. Made from the class run's results alone (class_results.h): never grades.

#include "grader/class_page/class_results.h"
#include "grader/class_page/gradebook.h"
#include "grader/class_page/similarity.h"
#include "grader/judge/diagnosis.h"
#include "grader/lab_catalog.h"

#include <filesystem>
#include <vector>

namespace raylab::grader {

struct ClassPageInput {
    const ClassResults& results;
    const LabCatalog& labs;
    const std::vector<Mistake>& mistakes;
    const SimilarityReport& similarity;
    const GradebookFiles& gradebook;
};

// OUT/index.html and OUT/similarity/*.html, each written whole.
void writeClassPage(const ClassPageInput& input, const std::filesystem::path& out);

} // namespace raylab::grader
