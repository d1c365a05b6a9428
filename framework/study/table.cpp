#include "table.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace raylab::study {

std::string sci(double value, int digits) {
    if (value == 0.) return "0";
    if (std::isnan(value)) return "nan";
    char text[32];
    std::snprintf(text, sizeof text, "%.*e", digits, value);
    return text;
}

std::string fixed(double value, int decimals) {
    if (std::isnan(value)) return "nan";
    char text[48];
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
    return text;
}

std::string toMarkdown(const Table& table) {
    std::string out = "**" + table.title + "**\n\n|";
    for (const std::string& c : table.columns) out += " " + c + " |";
    out += "\n|";
    for (std::size_t k = 0; k < table.columns.size(); ++k) out += "---|";
    out += "\n";
    for (const auto& row : table.rows) {
        out += "|";
        for (const std::string& cell : row) out += " " + cell + " |";
        out += "\n";
    }
    return out;
}

namespace {

std::string csvCell(const std::string& cell) {
    if (cell.find_first_of(",\"\n") == std::string::npos) return cell;
    std::string quoted = "\"";
    for (char ch : cell) quoted += ch == '"' ? std::string("\"\"") : std::string(1, ch);
    return quoted + "\"";
}

} // namespace

void writeCsv(const std::filesystem::path& folder, const Table& table) {
    std::filesystem::create_directories(folder);
    const std::filesystem::path file = folder / (table.id + ".csv");
    std::ofstream out(file);
    auto line = [&](const std::vector<std::string>& cells) {
        for (std::size_t k = 0; k < cells.size(); ++k) out << (k ? "," : "") << csvCell(cells[k]);
        out << "\n";
    };
    line(table.columns);
    for (const auto& row : table.rows) line(row);
    if (!out) throw std::runtime_error("cannot write " + file.string());
}

} // namespace raylab::study
