#pragma once
// A class run's results as the class page and the gradebook exports read them: every student of
// OUT/students/ whose grading finished (result.json) with their outcome (outcome.json), by name.

#include "grader/class_page/student_outcome.h"

#include <filesystem>
#include <string>
#include <vector>

namespace raylab::grader {

struct ClassMember {
    std::string student;          // as grades.csv shows the folder's name (printableName)
    std::filesystem::path place;  // OUT/students/<safe name>
    StudentOutcome outcome;
};

struct ClassResults {
    std::vector<ClassMember> students; // by name
    std::vector<std::string> problems; // a result without a readable outcome: named, left out
};

ClassResults loadClassResults(const std::filesystem::path& out);

} // namespace raylab::grader
