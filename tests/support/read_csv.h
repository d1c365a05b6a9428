#pragma once
// A CSV reader for the tests, as RFC 4180 and spreadsheets read it: a quoted field may hold commas,
// doubled quotes and line breaks.

#include <string>
#include <vector>

namespace raylab::test {

inline std::vector<std::vector<std::string>> readCsv(const std::string& text) {
    std::vector<std::vector<std::string>> rows;
    std::vector<std::string> row(1);
    bool quoted = false, any = false;
    for (std::size_t k = 0; k < text.size(); ++k) {
        const char c = text[k];
        any = true;
        if (quoted && c == '"' && k + 1 < text.size() && text[k + 1] == '"') {
            row.back() += '"';
            ++k;
        } else if (c == '"') {
            quoted = !quoted;
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
    if (any) rows.push_back(row);
    return rows;
}

} // namespace raylab::test
