#pragma once
// The points table: one TOML file the instructor edits (tests/grading/points.toml). A table per
// lab; each key is a function check's name or "figure <id>", each value its points.

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace raylab::grader {

struct PointsTable {
    std::filesystem::path file;
    // lab -> (check name or "figure <id>") -> points,.
    std::map<int, std::vector<std::pair<std::string, double>>> labs;

    // The points of an item; `fallback` when the table does not name it.
    double points(int lab, const std::string& item, double fallback = 1.) const;
    bool has(int lab, const std::string& item) const;
};

// Throws std::runtime_error naming the file and the key when the table cannot be used.
PointsTable loadPointsTable(const std::filesystem::path& file);

inline std::string figureItem(const std::string& id) { return "figure " + id; }

} // namespace raylab::grader
