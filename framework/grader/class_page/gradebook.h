#pragma once
// Grades for the course's gradebook, as its platforms import them: Moodle's grade import (a CSV with
// an identifier column the instructor maps to a user field, then a column per grade item) and the
// Gradescope/Canvas style (name, student id, email, then the items). A student is known by their
// folder's name, or by a roster (`--roster roster.csv`: folder, id, name, email). A roster's row is
// a student's when its folder is, byte for byte, that student's folder (the same ClassMember::id),
// never because the two print alike; every cell is printable (printableName) and a CSV cell as
// src/csv.h writes it.

#include "grader/class_page/class_results.h"

#include <filesystem>
#include <string>
#include <vector>

namespace raylab::grader {

struct RosterEntry {
    std::string folder, id, name, email;
};

// A CSV whose header names the columns folder, id, name and email (in any order; name and email may
// be absent). Throws std::runtime_error naming the file, the line and the problem (a column missing,
// a folder given twice, an empty folder or id).
std::vector<RosterEntry> readRoster(const std::filesystem::path& file);

struct GradebookFiles {
    std::vector<std::string> unknown;    // graded, but not in the roster: in neither file
    std::vector<std::string> missing;    // in the roster, with no result: a row with empty grades
    std::vector<std::string> unreadable; // a result without a readable outcome: no grade in either file
};

// OUT/gradebook-moodle.csv and OUT/gradebook-canvas.csv, a row per roster student (or per graded
// student without a roster), the items being each lab's points and the total.
GradebookFiles writeGradebooks(const ClassResults& results, const std::vector<RosterEntry>& roster,
                               const std::filesystem::path& out);

} // namespace raylab::grader
