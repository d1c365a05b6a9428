#pragma once
// The tests read the CSV files the grader writes as the grader reads a roster (framework/src/csv.h):
// as RFC 4180 and spreadsheets read them, a quoted field holding commas, doubled quotes and line breaks.

#include "src/csv.h"

#include <string>
#include <vector>

namespace raylab::test {

inline std::vector<std::vector<std::string>> readCsv(const std::string& text) { return csvRows(text); }

} // namespace raylab::test
