#pragma once
// A table of measurements: printed as Markdown, written as CSV and Markdown.

#include <filesystem>
#include <string>
#include <vector>

namespace raylab::study {

struct Table {
    std::string id;    // file name stem: <id>.csv
    std::string title; // one line: what was measured and how
    std::vector<std::string> columns;
    std::vector<std::vector<std::string>> rows;

    void add(std::vector<std::string> row) { rows.push_back(std::move(row)); }
};

// "1.23e-04", "0", "nan": numbers short enough for a table, exact enough to read.
std::string sci(double value, int digits = 2);
std::string fixed(double value, int decimals);

std::string toMarkdown(const Table& table);
// Writes DIR/<id>.csv; throws std::runtime_error naming the file when it cannot.
void writeCsv(const std::filesystem::path& folder, const Table& table);

} // namespace raylab::study
