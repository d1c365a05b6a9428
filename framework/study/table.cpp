#include "table.h"

#include "src/atomic_file.h"
#include "src/csv.h"

#include <cmath>
#include <cstdio>

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

void writeCsv(const std::filesystem::path& folder, const Table& table) {
    std::string csv = csvLine(table.columns);
    for (const auto& row : table.rows) csv += csvLine(row);
    writeFileAtomically(folder / (table.id + ".csv"), csv);
}

} // namespace raylab::study
