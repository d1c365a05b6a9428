// A class with three hostile students (issue 34's "done when", small): two honest students, a staller
// (bad_submissions/stops_itself: lab 1 stops itself with SIGSTOP), a forker (bad_submissions/forks: lab 3
// forks 100,000 children a call) and a flood (bad_builds/huge_error: lab 2's compile error is about
// 1 GB), graded end to end by `raylab grade-class` at its default limits, under bubblewrap and under
// the fallback. The honest students get every point; each hostile one loses its lab (the forker, the
// points of the function that forks), with the limit it hit named; the results stay small.
// scripts/measure_hostile_class.sh times a class of 30.
#include "grading_support.h"
#include "grader/sandbox/cgroup.h"
#include "support/files.h"
#include "support/read_csv.h"
#include "support/run_program.h"

#include <map>
#include <unistd.h>

using namespace raylab::test;

namespace {

// `student`'s copy of solutions/ in `classDir`, with `patch` (tests/instructors/...) applied when given.
void addStudent(const fs::path& classDir, const std::string& student, const std::string& patch = "") {
    fs::copy(sourceDir() / "solutions", classDir / student, fs::copy_options::recursive);
    if (patch.empty()) return;
    const ProgramRun applied = runProgram({"patch", "-s", "--batch", "-p1", "-d", (classDir / student).string(), "-i",
                                           (sourceDir() / "tests/instructors" / patch).string()},
                                          classDir.parent_path() / "patch-output.txt");
    REQUIRE_MESSAGE(applied.status == 0, applied.output);
}

// Each student's row of grades.csv, by the name of its first column.
std::map<std::string, std::map<std::string, std::string>> rowsOf(const fs::path& csv) {
    const auto rows = readCsv(readFile(csv));
    REQUIRE(!rows.empty());
    std::map<std::string, std::map<std::string, std::string>> byStudent;
    for (std::size_t r = 1; r < rows.size(); ++r)
        for (std::size_t c = 0; c < rows[r].size() && c < rows[0].size(); ++c)
            byStudent[rows[r][0]][rows[0][c]] = rows[r][c];
    return byStudent;
}

std::uintmax_t folderBytes(const fs::path& folder) {
    std::uintmax_t bytes = 0;
    for (const fs::directory_entry& entry : fs::recursive_directory_iterator(folder))
        if (entry.is_regular_file()) bytes += entry.file_size();
    return bytes;
}

} // namespace

TEST_SUITE("hostile class") {

TEST_CASE("a staller, a forker and a 1 GB compile error in a class: each loses its lab with the limit named, the others "
          "get every point, the results stay small; under bubblewrap and the fallback") {
    std::vector<std::string> sandboxes;
    if (bubblewrapMissing().empty()) sandboxes.push_back("bubblewrap");
    else MESSAGE("bubblewrap cannot run here (" << bubblewrapMissing() << "): not tested with it");
    if (geteuid() == 0) sandboxes.push_back("fallback");
    else MESSAGE("not root: the fallback is not tested");
    const fs::path root = freshFolder("raylab-hostile-class");
    const fs::path classDir = root / "class";
    fs::create_directories(classDir);
    addStudent(classDir, "alice");
    addStudent(classDir, "bob");
    addStudent(classDir, "staller", "bad_submissions/stops_itself.patch");
    addStudent(classDir, "forker", "bad_submissions/forks.patch");
    addStudent(classDir, "flood", "bad_builds/huge_error.patch");
    // A fork bomb is bounded by the run's cgroup (root); without one nothing would stop it here.
    const bool cgroup = raylab::grader::detail::RunCgroup(256, 4ull << 30).active();
    if (!cgroup) MESSAGE("no cgroup here: the forker is not graded, nothing would bound it");
    if (!cgroup) fs::remove_all(classDir / "forker");

    for (const std::string& sandbox : sandboxes) {
        CAPTURE(sandbox);
        const fs::path out = root / ("results-" + sandbox);
        // out/build: the depth of the other grading builds, whose objects the compiler cache shares.
        const ProgramRun run = runProgram({"/usr/bin/env", "RAYLAB_SANDBOX=" + sandbox, (binDir() / "raylab").string(),
                                           "grade-class", classDir.string(), "--out", out.string(), "--build-dir",
                                           (root / "out" / "build").string(), "--lang", "en"},
                                          root / ("output-" + sandbox + ".txt"), root);
        REQUIRE_MESSAGE(run.status == 0, run.output);
        auto rows = rowsOf(out / "grades.csv");
        for (const char* honest : {"alice", "bob"}) {
            CAPTURE(honest);
            CHECK_MESSAGE(rows[honest]["total"] == rows[honest]["max"], rows[honest]["problems"]);
        }
        // Each hostile student loses points in its lab (all of them, or those of the function that broke
        // the rules), keeps the other labs' points, and the limit it hit is named: in its row of
        // grades.csv for a lab, in its report for a check.
        const auto lost = [&](const std::string& student, const std::string& lab, const std::string& named,
                              bool wholeLab) {
            CAPTURE(student);
            std::map<std::string, std::string>& row = rows[student];
            if (wholeLab) CHECK(row[lab] == "0");
            else CHECK(std::stod(row[lab]) < std::stod(rows["alice"][lab]));
            const std::string said =
                wholeLab ? row["problems"] : readFile(out / "students" / student / "report" / "results.json");
            CHECK_MESSAGE(said.find(named) != std::string::npos, said);
            double others = 0., full = 0.;
            for (const auto& [column, value] : rows["alice"])
                if (column.rfind("lab", 0) == 0 && column != lab) {
                    full += std::stod(value);
                    others += std::stod(row[column]);
                }
            CHECK_MESSAGE(others == full, row["problems"]);
        };
        lost("staller", "lab1", "lab 1 used its", true);
        if (cgroup) lost("forker", "lab3", "too many processes (more than 256", false);
        lost("flood", "lab2", "the compiler's output was cut to 128 KB", true);
        // A gigabyte of compiler output costs its build log 128 KB; every student's results together a few MB.
        CHECK(fs::file_size(out / "students" / "flood" / "build.log") < (std::uintmax_t(256) << 10));
        CHECK(folderBytes(out) < (std::uintmax_t(16) << 20));
    }
    std::error_code ignored;
    fs::remove_all(root, ignored);
}

} // TEST_SUITE
