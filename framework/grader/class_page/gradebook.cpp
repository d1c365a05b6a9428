#include "grader/class_page/gradebook.h"

#include "grader/course/class_run.h"
#include "src/atomic_file.h"
#include "src/csv.h"
#include "src/text.h"

#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>

namespace raylab::grader {

namespace fs = std::filesystem;

namespace {

std::string number(double v) {
    std::ostringstream text;
    text << v;
    return text.str();
}

std::string trimmed(const std::string& text) {
    const std::size_t first = text.find_first_not_of(" \t");
    if (first == std::string::npos) return "";
    return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

// Every lab any student has points in, in order.
std::vector<int> gradedLabs(const ClassResults& results) {
    std::set<int> labs;
    for (const ClassMember& m : results.students)
        for (const LabScore& l : m.outcome.labs) labs.insert(l.lab);
    return {labs.begin(), labs.end()};
}

// A student's grade items: each lab's points (empty when that lab was not graded), then the total.
std::vector<std::string> gradeItems(const std::vector<int>& labs, const ClassMember* member) {
    std::vector<std::string> cells;
    for (int lab : labs) {
        std::string cell;
        if (member)
            for (const LabScore& l : member->outcome.labs)
                if (l.lab == lab) cell = number(l.points);
        cells.push_back(cell);
    }
    cells.push_back(member ? number(member->outcome.points()) : "");
    return cells;
}

} // namespace

std::vector<RosterEntry> readRoster(const fs::path& file) {
    const std::optional<std::string> text = readWholeFile(file);
    if (!text) throw std::runtime_error("cannot read the roster " + printablePath(file));
    std::vector<std::vector<std::string>> rows;
    try {
        rows = csvRows(*text);
    } catch (const std::exception& e) {
        throw std::runtime_error(printablePath(file) + ": " + e.what());
    }
    if (rows.empty()) throw std::runtime_error(printablePath(file) + ": empty (its first line names the columns folder,id,name,email)");
    std::map<std::string, std::size_t> column;
    for (std::size_t k = 0; k < rows[0].size(); ++k) column[trimmed(rows[0][k])] = k;
    for (const char* needed : {"folder", "id"})
        if (!column.count(needed))
            throw std::runtime_error(printablePath(file) + ":1: no column '" + needed +
                                     "' (the first line names the columns folder,id,name,email)");
    const auto cell = [&](const std::vector<std::string>& row, const char* name) {
        const auto it = column.find(name);
        return it != column.end() && it->second < row.size() ? trimmed(row[it->second]) : std::string();
    };
    std::vector<RosterEntry> roster;
    std::set<std::string> folders;
    for (std::size_t r = 1; r < rows.size(); ++r) {
        const std::string where = printablePath(file) + ":" + std::to_string(r + 1) + ": ";
        if (rows[r].size() == 1 && trimmed(rows[r][0]).empty()) continue; // a blank line
        RosterEntry entry{cell(rows[r], "folder"), cell(rows[r], "id"), cell(rows[r], "name"), cell(rows[r], "email")};
        if (entry.folder.empty()) throw std::runtime_error(where + "no folder name");
        if (entry.id.empty()) throw std::runtime_error(where + "no id for '" + printableName(entry.folder) + "'");
        if (!folders.insert(entry.folder).second)
            throw std::runtime_error(where + "the folder '" + printableName(entry.folder) + "' is given twice");
        roster.push_back(std::move(entry));
    }
    return roster;
}

GradebookFiles writeGradebooks(const ClassResults& results, const std::vector<RosterEntry>& roster, const fs::path& out) {
    const std::vector<int> labs = gradedLabs(results);
    std::vector<std::string> items;
    for (int lab : labs) items.push_back("lab" + std::to_string(lab));
    items.emplace_back("total");

    // A row of either file: who it names, as shown, and whose grades it holds.
    struct Row {
        std::string id, email, name;
        const ClassMember* member = nullptr;
    };
    std::map<std::string, const ClassMember*> byId;
    for (const ClassMember& m : results.students) byId[m.id] = &m;
    std::vector<Row> rows;
    GradebookFiles files;
    files.unreadable = results.unreadable;
    if (roster.empty()) {
        for (const ClassMember& m : results.students) rows.push_back({m.student, "", m.student, &m});
    } else {
        std::set<std::string> listed;
        for (const RosterEntry& r : roster) {
            const std::string id = safeStudentName(r.folder);
            listed.insert(id);
            const auto member = byId.find(id);
            if (member == byId.end()) files.missing.push_back(printableName(r.folder));
            rows.push_back({printableName(r.id), printableName(r.email), printableName(r.name),
                            member != byId.end() ? member->second : nullptr});
        }
        for (const ClassMember& m : results.students)
            if (!listed.count(m.id)) files.unknown.push_back(m.student);
    }

    std::vector<std::string> header{"ID number", "Email address", "Full name"};
    header.insert(header.end(), items.begin(), items.end());
    std::string moodle = csvLine(header);
    header = {"Name", "SID", "Email"};
    header.insert(header.end(), items.begin(), items.end());
    std::string canvas = csvLine(header);
    for (const Row& r : rows) {
        const std::vector<std::string> grades = gradeItems(labs, r.member);
        std::vector<std::string> line{r.id, r.email, r.name};
        line.insert(line.end(), grades.begin(), grades.end());
        moodle += csvLine(line);
        line = {r.name, r.id, r.email};
        line.insert(line.end(), grades.begin(), grades.end());
        canvas += csvLine(line);
    }
    writeFileAtomically(out / "gradebook-moodle.csv", moodle);
    writeFileAtomically(out / "gradebook-canvas.csv", canvas);
    return files;
}

} // namespace raylab::grader
