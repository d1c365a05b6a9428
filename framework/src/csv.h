#pragma once
// CSV as spreadsheets and RFC 4180 read it: a cell holding a comma, a quote or a line break is
// quoted, its quotes doubled; any other cell is written as it is.

#include <string>
#include <vector>

namespace raylab {

// One line of cells, ending with "\n".
std::string csvLine(const std::vector<std::string>& cells);

} // namespace raylab
