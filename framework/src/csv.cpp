#include "src/csv.h"

#include <regex>
#include <stdexcept>

namespace raylab {

namespace {

// "-1.5", "+2", "-3e-4": what a spreadsheet reads as a number, never as a formula.
bool isPlainNumber(const std::string& cell) {
    static const std::regex number(R"([+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?)");
    return std::regex_match(cell, number);
}

// `cell` with a ' before each part a spreadsheet would run as a formula. A part starts at the cell's
// start and after each separator a spreadsheet may split at (',', ';', a tab) or a line break, for
// one that splits inside quotes or ignores them; its quotes and spaces there are skipped (a reader
// that drops the quotes, or trims the spaces, starts it at what follows). It is run when it starts
// with = + - @, a tab or a carriage return and is not a plain number (up to the next separator).
std::string defused(const std::string& cell) {
    static const std::string separators = ",;\t\r\n", triggers = "=+-@\t\r";
    std::string out;
    bool start = true;
    for (std::size_t at = 0; at < cell.size(); ++at) {
        const char c = cell[at];
        if (start && triggers.find(c) != std::string::npos) {
            const std::size_t end = cell.find_first_of(separators, at + 1);
            if (!isPlainNumber(cell.substr(at, end == std::string::npos ? std::string::npos : end - at))) out += '\'';
        }
        out += c;
        if (separators.find(c) != std::string::npos) start = true;
        else if (c != '"' && c != ' ') start = false;
    }
    return out;
}

// Quoted when it holds a separator of any spreadsheet's (',', ';', a tab), a quote or a line break.
std::string csvCell(const std::string& raw) {
    const std::string cell = defused(raw);
    if (cell.find_first_of(",;\t\"\r\n") == std::string::npos) return cell;
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

std::vector<std::vector<std::string>> csvRows(const std::string& text) {
    std::vector<std::vector<std::string>> rows;
    std::vector<std::string> row(1);
    bool quoted = false, any = false;
    int line = 1, quoteLine = 0;
    const std::size_t start = text.rfind("\xEF\xBB\xBF", 0) == 0 ? 3 : 0;
    for (std::size_t k = start; k < text.size(); ++k) {
        const char c = text[k];
        any = true;
        if (c == '\n') ++line;
        if (quoted && c == '"' && k + 1 < text.size() && text[k + 1] == '"') {
            row.back() += '"';
            ++k;
        } else if (c == '"') {
            quoted = !quoted;
            quoteLine = line;
        } else if (!quoted && c == ',') {
            row.emplace_back();
        } else if (!quoted && c == '\n') {
            rows.push_back(row);
            row.assign(1, "");
            any = false;
        } else if (!(c == '\r' && !quoted && k + 1 < text.size() && text[k + 1] == '\n')) {
            row.back() += c;
        }
    }
    if (quoted) throw std::runtime_error("line " + std::to_string(quoteLine) + ": a quote is opened and never closed");
    if (any) rows.push_back(row);
    return rows;
}

} // namespace raylab
