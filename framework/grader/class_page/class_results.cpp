#include "grader/class_page/class_results.h"

#include "grader/course/class_run.h"
#include "src/text.h"

#include <algorithm>
#include <stdexcept>
#include <system_error>
#include <tuple>

namespace raylab::grader {

namespace fs = std::filesystem;

ClassResults loadClassResults(const fs::path& out) {
    ClassResults results;
    const fs::path students = out / "students";
    std::error_code error;
    for (auto it = fs::directory_iterator(students, error); !error && it != fs::directory_iterator(); it.increment(error)) {
        const std::optional<StudentRecord> record = readStudentResult(it->path());
        if (!record) continue; // not graded yet, or its grading did not finish
        try {
            results.students.push_back({it->path().filename().string(), record->student, it->path(),
                                        readStudentOutcome(it->path() / "outcome.json")});
        } catch (const std::exception& e) {
            results.problems.push_back(record->student + ": " + e.what());
            results.unreadable.push_back(record->student);
        }
    }
    if (error) throw std::runtime_error("cannot read " + printablePath(students) + ": " + error.message());
    std::sort(results.students.begin(), results.students.end(),
              [](const ClassMember& a, const ClassMember& b) { return std::tie(a.student, a.id) < std::tie(b.student, b.id); });
    return results;
}

} // namespace raylab::grader
