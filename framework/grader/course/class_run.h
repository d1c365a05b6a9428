#pragma once
// A class run is a ledger (`raylab grade-class`): one folder per student under OUT/students/, whose
// result.json is written atomically when, and only when, that student's grading finished; grades.csv
// is regenerated from those results, so an interrupted run resumes where it stopped and never
// duplicates or loses a row. One run at a time per OUT (a lock); SIGINT and SIGTERM stop the run
// cleanly: the student being graded is left ungraded and the next run grades them; so does a full
// disk, said once (isDiskFull), the student marked "not graded: disk full". No process of a
// run outlives it, and only the run holds the lock, so the next run starts at once after a SIGKILL.

#include <exception>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace raylab::grader {

using Settings = std::vector<std::pair<std::string, std::string>>; // name, value

// A student's row of grades.csv: the folder's name as printableName (src/text.h) shows it, and the cells after
// it, by column; and what made it (the run's `madeBy`). Read back (readStudentResult), the name is made
// again from the folder's (OUT/students/<safe name>) bytes, but for a cut safe name.
struct StudentRecord {
    std::string student;
    std::vector<std::pair<std::string, std::string>> cells; // column, value
    Settings madeBy = {};
};

// Where a student is graded.
struct StudentWork {
    std::string name;                 // the folder's real name
    std::filesystem::path submission; // CLASS/<name>
    std::filesystem::path folder;     // OUT/students/<safe name>: build/, report/, result.json
};

// Grades one student (building in work.folder / "build", reports in work.folder / "report") and
// returns their row. On POSIX it runs in a process of its own, in its own process group with all it
// starts: the run stops it when interrupted, kills the group when it ends, and it dies with the run
// (killed with SIGKILL too).
using GradeStudent = std::function<StudentRecord(const StudentWork& work)>;

struct ClassRunOptions {
    std::filesystem::path classFolder; // one folder per student
    std::filesystem::path out;         // grades.csv, students/, the lock
    bool wait = false;                 // another run holds OUT: wait for it instead of refusing
    // What makes a result (labs, timeout, grader version, sandbox...): written in each result, and a
    // result made otherwise is not this run's: that student is graded again, and left out of
    // grades.csv until they are.
    Settings madeBy;
    std::vector<int> runOnlyDescriptors; // locks the run holds: each student's process closes them
    // Run once before the first student to grade (not at all when every student has a result), in a
    // process of its own that a stop ends as it ends a student's: what the students share, such as
    // the framework's build.
    std::function<void()> beforeFirstStudent;
    // Run once every student was tried, holding the lock, unless the run stopped (a signal, a full
    // disk): what is made from every result, such as the class page.
    std::function<void()> afterLastStudent;
};

// While one lives, SIGINT and SIGTERM only ask the class run to stop (runClass holds one). A command
// with work after the run (removing its scratch folder) holds one across it too: a signal that comes
// once the run has ended then changes nothing, instead of killing the process halfway out.
class StopSignals {
public:
    StopSignals();
    ~StopSignals();
    StopSignals(const StopSignals&) = delete;
    StopSignals& operator=(const StopSignals&) = delete;
};

// Grades every student of the class not graded yet. Returns the exit status: 0; 1 when OUT is held
// by another run, a student's grading did not finish, or a disk was full (the run stopped there);
// 128 + the signal when interrupted (130 for SIGINT, 143 for SIGTERM).
int runClass(const ClassRunOptions& options, const GradeStudent& grade);

// The result in a student's folder (OUT/students/<safe name>/result.json); nothing while their
// grading has not finished.
std::optional<StudentRecord> readStudentResult(const std::filesystem::path& studentFolder);

// Whether `e` says a disk is full (ENOSPC, or EDQUOT: a quota): a WriteError or a file system error.
// A class run stops on it, saying so once; the student being graded is left for the next run. So
// grade-class passes it on rather than grade the student as a build failure.
bool isDiskFull(const std::exception& e);

// A file name for any folder name, one to one: ASCII letters and digits, '_', and '-' and '.' after
// the first character are kept, every other byte is written %XX. A name whose form is longer than
// 160 bytes is cut and ends with '~' and a 64-bit hash of the whole name.
std::string safeStudentName(const std::string& folderName);

// The folder's name a safe name was made from; nothing for a cut one (or one safeStudentName never makes).
std::optional<std::string> studentFolderName(const std::string& safeName);

// A problem as a cell of grades.csv: its first line and its first three error lines (a build
// problem may have a cause per lab), each cut at a word past 200 characters.
std::string problemSummary(const std::string& problem);

} // namespace raylab::grader
