#include "grader/points.h"

#include <toml++/toml.h>

#include <stdexcept>

namespace raylab::grader {

double PointsTable::points(int lab, const std::string& item, double fallback) const {
    const auto it = labs.find(lab);
    if (it == labs.end()) return fallback;
    for (const auto& [name, value] : it->second)
        if (name == item) return value;
    return fallback;
}

bool PointsTable::has(int lab, const std::string& item) const {
    const auto it = labs.find(lab);
    if (it == labs.end()) return false;
    for (const auto& entry : it->second)
        if (entry.first == item) return true;
    return false;
}

PointsTable loadPointsTable(const std::filesystem::path& file) {
    toml::table t;
    try {
        t = toml::parse_file(file.string());
    } catch (const toml::parse_error& e) {
        throw std::runtime_error(file.string() + ":" + std::to_string(e.source().begin.line) + ": " +
                                 std::string(e.description()));
    }
    PointsTable table;
    table.file = file;
    for (const auto& [key, node] : t) {
        const std::string name(key.str());
        if (name.size() != 4 || name.rfind("lab", 0) != 0 || name[3] < '1' || name[3] > '5')
            throw std::runtime_error(file.string() + ": [" + name + "]: expected the tables [lab1] ... [lab5]");
        const toml::table* lab = node.as_table();
        if (!lab) throw std::runtime_error(file.string() + ": " + name + " must be a table");
        auto& items = table.labs[name[3] - '0'];
        for (const auto& [itemKey, value] : *lab) {
            const std::optional<double> points = value.value<double>();
            if (!points || *points < 0.)
                throw std::runtime_error(file.string() + ": [" + name + "] \"" + std::string(itemKey.str()) +
                                         "\": points must be a number >= 0");
            items.emplace_back(std::string(itemKey.str()), *points);
        }
    }
    return table;
}

} // namespace raylab::grader
