#pragma once
// The reports of a grade, all in one folder: index.html (for people), results.json (Gradescope's
// autograder format) and junit.xml (for CI), plus the pictures the page shows.

#include "grader/judge/outcome.h"

#include <filesystem>
#include <string>

namespace raylab::grader {

void writeHtmlReport(const GradeResult& result, const ReferenceSet& references, const std::filesystem::path& folder);
void writeGradescopeJson(const GradeResult& result, const std::filesystem::path& file);
void writeJUnitXml(const GradeResult& result, const std::filesystem::path& file);

// All three into `folder` (created).
void writeReports(const GradeResult& result, const ReferenceSet& references, const std::filesystem::path& folder);

// The terminal's view: a line per check and figure, the labs' scores and the problems.
std::string terminalSummary(const GradeResult& result);

} // namespace raylab::grader
