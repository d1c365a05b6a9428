#pragma once
// A class run's results as the class page and the gradebook exports read them: every student of
// OUT/students/ whose grading finished (result.json) with their outcome (outcome.json), by name.
// A student is who their folder is: `id`, the name of OUT/students/<safe name> (safeStudentName, one
// to one with the folder's bytes), is what every join uses (a roster's row, a gradebook's, a pair of
// similar submissions); `student` is only shown, made printable once, when they were graded.

#include "grader/class_page/student_outcome.h"

#include <filesystem>
#include <string>
#include <vector>

namespace raylab::grader {

struct ClassMember {
    std::string id;               // the safe name (class_run.h's safeStudentName of the folder's name)
    std::string student;          // as grades.csv shows the folder's name (printableName): never a key
    std::filesystem::path place;  // OUT/students/<safe name>
    StudentOutcome outcome;
};

struct ClassResults {
    std::vector<ClassMember> students; // by name shown, then by id
    std::vector<std::string> problems; // a result without a readable outcome: named, left out
    std::vector<std::string> unreadable; // those students, as shown
};

ClassResults loadClassResults(const std::filesystem::path& out);

} // namespace raylab::grader
