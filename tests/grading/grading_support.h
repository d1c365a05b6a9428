#pragma once
// Helpers of the grader's end-to-end tests: the course's references and labs, and grading an
// agent built by tests/grading/CMakeLists.txt.

#include "grader/judge/grade.h"
#include "src/messages.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <set>
#include <string>
#include <vector>

namespace raylab::test {

namespace fs = std::filesystem;
using namespace raylab::grader;

inline fs::path binDir() { return RAYLAB_GRADING_BIN; }
inline fs::path sourceDir() { return RAYLAB_SOURCE_DIR; }
// The course's reference folders, each lab's in its grading folder.
inline std::vector<fs::path> referenceDirs() {
    std::vector<fs::path> folders;
    for (const LabDescription& lab : loadLabCatalog(sourceDir() / "labs").labs)
        folders.push_back(sourceDir() / "framework/grader/labs" / lab.id / "references");
    return folders;
}

// A lab's points in the catalogue: its checks' and its figures'.
inline double labPoints(const LabDescription& lab) {
    double points = 0.;
    for (const LabCheck& c : lab.checks) points += c.points;
    for (const LabFigure& f : lab.figures) points += f.points;
    return points;
}

// The course's total in the catalogue.
inline double catalogTotal() {
    double total = 0.;
    for (const LabDescription& lab : loadLabCatalog(sourceDir() / "labs").labs) total += labPoints(lab);
    return total;
}

// The points cells of a grades.csv row, as the catalogue makes them: each lab's (lab<N>, in the
// course's order) with the labs `lost` at 0, then the total and the max.
inline std::vector<std::string> expectedPointsCells(const std::set<int>& lost = {}) {
    std::vector<std::string> cells;
    double total = 0.;
    for (const LabDescription& lab : loadLabCatalog(sourceDir() / "labs").labs) {
        const double points = lost.count(lab.number) ? 0. : labPoints(lab);
        cells.push_back(formatNumber(points));
        total += points;
    }
    cells.push_back(formatNumber(total));
    cells.push_back(formatNumber(catalogTotal()));
    return cells;
}

// Every lab of the course, by number.
inline std::set<int> everyLab() {
    std::set<int> numbers;
    for (const LabDescription& lab : loadLabCatalog(sourceDir() / "labs").labs) numbers.insert(lab.number);
    return numbers;
}

// Lab `lab` and the labs that use it, by number: those a broken lab costs where no reference stands
// in for it (the students' tree).
inline std::vector<int> labAndItsUsers(const LabCatalog& catalog, int lab) {
    std::vector<int> labs;
    for (const LabDescription& l : catalog.labs)
        if (l.number == lab || std::find(l.uses.begin(), l.uses.end(), lab) != l.uses.end()) labs.push_back(l.number);
    return labs;
}

// The last lab of the course that another lab of it uses (where no reference stands in for it, its
// breaking costs its users too); the last lab when none is used.
inline LabDescription usedLab(const LabCatalog& catalog) {
    for (auto lab = catalog.labs.rbegin(); lab != catalog.labs.rend(); ++lab)
        if (labAndItsUsers(catalog, lab->number).size() > 1) return *lab;
    return catalog.labs.back();
}

// The course's labs of solutions/ copied into `to` (<lab>/<files>), as a student uploads them.
inline void copyCourseSolutions(const fs::path& to) {
    fs::create_directories(to);
    for (const LabDescription& lab : loadLabCatalog(sourceDir() / "labs").labs)
        fs::copy(sourceDir() / "solutions" / lab.id, to / lab.id, fs::copy_options::recursive);
}

// grades.csv's header as the catalogue makes it.
inline std::vector<std::string> expectedCsvHeader() {
    std::vector<std::string> header{"student"};
    for (const LabDescription& lab : loadLabCatalog(sourceDir() / "labs").labs)
        header.push_back("lab" + std::to_string(lab.number));
    header.insert(header.end(), {"total", "max", "problems"});
    return header;
}

// A figure's reference picture, in its lab's reference folder.
inline fs::path referencePicture(const std::string& figure) {
    for (const fs::path& folder : referenceDirs())
        if (fs::exists(folder / (figure + ".png"))) return folder / (figure + ".png");
    FAIL("no reference picture " << figure);
    return {};
}

// The course's references gathered in one folder `to`, as --references and --out take them (the
// labs' mistakes.toml one after the other: a list of [[mistake]] tables).
inline void copyReferences(const fs::path& to) {
    fs::create_directories(to);
    std::string mistakes;
    for (const fs::path& folder : referenceDirs())
        for (const auto& entry : fs::directory_iterator(folder)) {
            if (entry.path().filename() != "mistakes.toml") {
                fs::copy(entry.path(), to / entry.path().filename(), fs::copy_options::recursive);
                continue;
            }
            std::ifstream in(entry.path(), std::ios::binary);
            mistakes += std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()) + "\n";
        }
    std::ofstream(to / "mistakes.toml", std::ios::binary) << mistakes;
}

// The reference pictures a tree (a copy handed out) lacks: each lab's figures in its grading folder.
inline std::vector<std::string> missingReferences(const fs::path& tree) {
    std::vector<std::string> missing;
    for (const LabDescription& lab : loadLabCatalog(tree / "labs").labs)
        for (const LabFigure& f : lab.figures) {
            const fs::path file = fs::path("framework/grader/labs") / lab.id / "references" / (f.id + ".png");
            if (!fs::exists(tree / file)) missing.push_back(file.generic_string());
        }
    return missing;
}

// A setup with a scratch folder of its own (tests run in parallel).
inline GradeSetup courseSetup(const std::vector<fs::path>& references = referenceDirs()) {
    std::random_device random;
    GradeSetup setup = loadGradeSetup(references, sourceDir() / "labs", {},
                                      fs::temp_directory_path() / ("raylab-grading-test-" + std::to_string(random())));
    setup.limits.wallSeconds = 60.;
    setup.threads = 2;
    return setup;
}

inline GradeResult gradeAgent(const GradeSetup& setup, const std::string& agent) {
    const fs::path program = binDir() / agent;
    REQUIRE_MESSAGE(fs::exists(program), program.string() << " is not built");
    GradeResult result = gradeCode(setup, {{program, 0}}, false);
    fs::remove_all(setup.scratch);
    return result;
}

inline const CheckOutcome* findCheck(const GradeResult& r, const std::string& name) {
    for (const CheckOutcome& c : r.checks)
        if (c.name == name) return &c;
    return nullptr;
}

inline const FigureOutcome* findFigure(const GradeResult& r, const std::string& id) {
    for (const FigureOutcome& f : r.figures)
        if (f.id == id) return &f;
    return nullptr;
}

inline std::string failures(const GradeResult& r) {
    std::string text;
    for (const CheckOutcome& c : r.checks)
        if (!c.passed) text += "\n  check " + c.name + ": " + c.message;
    for (const FigureOutcome& f : r.figures)
        if (!f.passed) text += "\n  figure " + f.id + ": " + f.reason;
    for (const std::string& p : r.problems) text += "\n  problem: " + p;
    return text;
}

} // namespace raylab::test
