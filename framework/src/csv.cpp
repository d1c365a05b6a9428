#include "src/csv.h"

#include <regex>

namespace raylab {

namespace {

// "-1.5", "+2", "-3e-4": what a spreadsheet reads as a number, never as a formula.
bool isPlainNumber(const std::string& cell) {
    static const std::regex number(R"([+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?)");
    return std::regex_match(cell, number);
}

std::string defused(const std::string& cell) {
    if (cell.empty() || cell.find_first_of("=+-@\t\r") != 0 || isPlainNumber(cell)) return cell;
    return "'" + cell;
}

std::string csvCell(const std::string& raw) {
    const std::string cell = defused(raw);
    if (cell.find_first_of(",\"\r\n") == std::string::npos) return cell;
    std::string quoted = "\"";
    for (char c : cell) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
}

} // namespace

std::string csvLine(const std::vector<std::string>& cells) {
    std::string line;
    for (std::size_t k = 0; k < cells.size(); ++k) {
        if (k > 0) line += ',';
        line += csvCell(cells[k]);
    }
    line += '\n';
    return line;
}

} // namespace raylab
