// Submissions as students upload them, graded end to end by `raylab grade --labs`: the grader copies
// the lab files itself (regular files with the names lab.toml declares, nothing followed), wherever
// they are, and a lab that does not compile costs that lab and the labs that use it only.
// The cases share one build folder: after the first, each recompiles only the lab files that changed.
#include "grading_support.h"
#include "grader/course/submission.h"
#include "grader/sandbox/process.h"
#include "support/files.h"
#include "support/run_program.h"

#include <algorithm>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <unistd.h>
#include <utility>
#include <vector>

using namespace raylab::test;

namespace {

// This tree's own folder in the temporary folder; the build folder at the depth of the class tests'
// (tests/grading/CMakeLists.txt: their compile commands are the same, the compiler cache shares them).
const fs::path kRoot = scratchPath("raylab-grading-uploads");
const fs::path kBuild = kRoot / "out" / "build";

// A submission folder of its own, made empty.
fs::path submission(const std::string& name) {
    const fs::path folder = kRoot / "submissions" / name;
    fs::remove_all(folder);
    fs::create_directories(folder);
    return folder;
}

void write(const fs::path& file, const std::string& text) {
    fs::create_directories(file.parent_path());
    std::ofstream(file, std::ios::binary) << text;
}

struct Graded {
    int status = -1;
    std::string output;
    std::map<int, std::string> labs; // "10 / 10" for each lab's line
    std::string total;               // "points / max"
};

// `raylab grade --labs FOLDER`, in English, in the cases' shared build folder; `sandbox` not empty:
// with RAYLAB_SANDBOX=`sandbox`.
Graded grade(const fs::path& folder, const std::string& sandbox = "") {
    std::vector<std::string> argv{(binDir() / "raylab").string(), "grade", "--labs", folder.string(), "--build-dir",
                                  kBuild.string(), "--report", (kRoot / "report").string(), "--lang", "en"};
    if (!sandbox.empty()) argv.insert(argv.begin(), {"/usr/bin/env", "RAYLAB_SANDBOX=" + sandbox});
    const ProgramRun run = runProgram(argv, kRoot / "output.txt", kRoot);
    Graded g{run.status, run.output, {}, {}};
    std::istringstream lines(run.output);
    const std::regex labLine(R"(^  lab (\d+): (.* / .*) points$)"), totalLine(R"(^  total: (.*)$)");
    std::smatch match;
    for (std::string line; std::getline(lines, line);) {
        if (std::regex_match(line, match, labLine)) g.labs[std::stoi(match[1])] = match[2];
        if (std::regex_match(line, match, totalLine)) g.total = match[1];
    }
    return g;
}

// Every lab file of the course, <lab>/<file>, with its lab's number.
std::vector<std::pair<int, std::string>> labFiles() {
    std::vector<std::pair<int, std::string>> files;
    for (const LabDescription& lab : loadLabCatalog(sourceDir() / "labs").labs)
        for (const std::string& file : lab.files()) files.emplace_back(lab.number, lab.id + "/" + file);
    return files;
}

// The console's "points / max" of the total, and of each lab, as the catalogue makes them with the
// labs `lost` at 0.
std::string expectedTotal(const std::set<int>& lost = {}) {
    const std::vector<std::string> cells = expectedPointsCells(lost);
    return cells[cells.size() - 2] + " / " + cells.back();
}

std::map<int, std::string> expectedLabs(const std::set<int>& lost = {}) {
    const std::vector<std::string> cells = expectedPointsCells(lost), full = expectedPointsCells();
    std::map<int, std::string> labs;
    const std::vector<LabDescription> course = loadLabCatalog(sourceDir() / "labs").labs;
    for (std::size_t k = 0; k < course.size(); ++k) labs[course[k].number] = cells[k] + " / " + full[k];
    return labs;
}

} // namespace

TEST_SUITE("uploads") {

TEST_CASE("extra files named x;y.cpp, ${HOME}x.cpp or it's a \"file\".cpp cost nothing: listed, never given to CMake") {
    fs::create_directories(kRoot);
    const fs::path folder = submission("odd-names");
    copyCourseSolutions(folder);
    for (const char* name : {"x;y.cpp", "${HOME}x.cpp", "it's a \"file\".cpp"})
        write(folder / "lab3_sphere" / name, "this is not C++\n");
    const Graded g = grade(folder);
    CHECK_MESSAGE(g.total == expectedTotal(), g.output);
    CHECK(g.output.find("left out of the grade (3; the lab files are") != std::string::npos);
    CHECK(g.output.find("lab3_sphere/x;y.cpp: not a lab file") != std::string::npos);
    CHECK(g.output.find("lab3_sphere/it's a \"file\".cpp: not a lab file") != std::string::npos);
    CHECK(g.output.find("CMake Error") == std::string::npos);
}

TEST_CASE("the lab files uploaded flat, with __MACOSX and junk, earn every point") {
    const fs::path folder = submission("flat");
    for (const auto& [lab, file] : labFiles())
        fs::copy_file(sourceDir() / "solutions" / file, folder / fs::path(file).filename());
    write(folder / "__MACOSX" / "._look_at.cpp", "resource fork");
    write(folder / "__MACOSX" / "look_at.cpp", "not C++ either");
    write(folder / ".DS_Store", "junk");
    write(folder / "screenshot.png", "not a PNG");
    const Graded g = grade(folder);
    CHECK_MESSAGE(g.total == expectedTotal(), g.output);
    CHECK(g.output.find("left out of the grade") == std::string::npos);
}

TEST_CASE("folders named otherwise (tp3/, \"Lab 3/\") inside a wrapping folder earn every point") {
    const fs::path folder = submission("named-otherwise");
    // Lab N's files in tp1/, "TP 2/", "Lab 3/", lab4-final/, tp5/... by its number.
    const std::vector<std::string> forms{"lab#-final", "tp#", "TP #", "Lab #"};
    for (const auto& [lab, file] : labFiles()) {
        std::string name = forms[lab % forms.size()];
        name.replace(name.find('#'), 1, std::to_string(lab));
        const fs::path to = folder / "my labs" / name / fs::path(file).filename();
        fs::create_directories(to.parent_path());
        fs::copy_file(sourceDir() / "solutions" / file, to);
    }
    const Graded g = grade(folder);
    CHECK_MESSAGE(g.total == expectedTotal(), g.output);
}

TEST_CASE("a labs/ folder that is a link to solutions/ earns 0 and says why") {
    const fs::path folder = submission("linked-labs");
    fs::create_directory_symlink(sourceDir() / "solutions", folder / "labs");
    const Graded g = grade(folder);
    CHECK_MESSAGE(g.total == expectedTotal(everyLab()), g.output);
    CHECK(g.output.find("no lab file found: upload the lab files (gradient.cpp, ") != std::string::npos);
    CHECK(g.output.find("labs: a symbolic link, not followed") != std::string::npos);
    CHECK(g.output.find("does not build") == std::string::npos);
}

TEST_CASE("a lab file that is a link to its solution is not read: that lab is graded as not written") {
    const fs::path folder = submission("linked-file");
    copyCourseSolutions(folder);
    const LabDescription lab = usedLab(loadLabCatalog(sourceDir() / "labs"));
    const std::string file = lab.id + "/" + lab.files().front();
    fs::remove(folder / file);
    fs::create_symlink(sourceDir() / "solutions" / file, folder / file);
    const Graded g = grade(folder);
    CHECK_MESSAGE(g.labs.count(lab.number) == 1, g.output);
    CHECK(g.labs.at(lab.number) == expectedLabs({lab.number}).at(lab.number));
    CHECK(g.total == expectedTotal({lab.number}));
    CHECK(g.output.find(file + ": a symbolic link, not followed") != std::string::npos);
}

TEST_CASE("a folder with no lab file says what to upload, never that the code does not build") {
    const fs::path folder = submission("empty");
    write(folder / "README.md", "my labs are on my other computer\n");
    const Graded g = grade(folder);
    CHECK_MESSAGE(g.total == expectedTotal(everyLab()), g.output);
    CHECK(g.output.find("no lab file found: upload the lab files") != std::string::npos);
    CHECK(g.output.find("does not build") == std::string::npos);
}

TEST_CASE("a lab that does not build, one other labs use, costs that lab only: the other labs keep their points") {
    const fs::path folder = submission("used-lab-broken");
    copyCourseSolutions(folder);
    const LabDescription lab = usedLab(loadLabCatalog(sourceDir() / "labs"));
    const fs::path source = folder / lab.id / lab.files().front();
    write(source, "this line is not C++\n" + readFile(source));
    const Graded g = grade(folder);
    CHECK_MESSAGE(g.total == expectedTotal({lab.number}), g.output);
    CHECK(g.labs == expectedLabs({lab.number}));
    CHECK(g.output.find("lab " + std::to_string(lab.number) + ": the code does not build") != std::string::npos);
    CHECK(g.output.find(lab.files().front()) != std::string::npos); // the compiler's message names the file
}

TEST_CASE("a submission folder named with a newline and an escape sequence: one printable line on the console, every point") {
    const fs::path folder = submission("new\nline\x1B[2J");
    copyCourseSolutions(folder);
    const Graded g = grade(folder);
    CHECK_MESSAGE(g.total == expectedTotal(), g.output);
    CHECK_MESSAGE(g.output.find("building " + (kRoot / "submissions").generic_string() + "/new\\nline\\x1B[2J in ") !=
                      std::string::npos, g.output);
    CHECK_MESSAGE(g.output.find('\x1B') == std::string::npos, g.output);
}

// Every file of the build folder, the largest first.
std::vector<std::pair<std::uintmax_t, fs::path>> largestFiles(const fs::path& folder) {
    std::vector<std::pair<std::uintmax_t, fs::path>> files;
    for (const auto& entry : fs::recursive_directory_iterator(folder))
        if (entry.is_regular_file()) files.emplace_back(entry.file_size(), entry.path());
    std::sort(files.rbegin(), files.rend());
    return files;
}

// Under bubblewrap and under the fallback (as root), as every hostile case.
std::vector<std::string> sandboxes() {
    std::vector<std::string> all{""};
    if (geteuid() == 0) all.push_back("fallback");
    return all;
}

TEST_CASE("a lab file that makes a 100 MB object costs its lab, the 32 MB limit named; nothing of it stays in the build folder") {
    for (const std::string& sandbox : sandboxes()) {
        CAPTURE(sandbox);
        const fs::path folder = submission("big-object");
        copyCourseSolutions(folder);
        const LabDescription lab = loadLabCatalog(sourceDir() / "labs").labs.back();
        const fs::path source = folder / lab.id / lab.files().front();
        write(source, readFile(source) + "asm(\".section .rodata\\n.fill 100000000, 1, 1\\n.text\");\n");
        const Graded g = grade(folder, sandbox);
        CHECK_MESSAGE(g.total == expectedTotal({lab.number}), g.output);
        CHECK(g.labs.at(lab.number) == expectedLabs({lab.number}).at(lab.number));
        CHECK_MESSAGE(g.output.find("the compiler stopped at the 32 MB limit on each file it writes") != std::string::npos, g.output);
        CHECK(g.output.find("File size limit exceeded") == std::string::npos); // the build tool's words, replaced
        const auto files = largestFiles(kBuild);
        REQUIRE(!files.empty());
        CHECK_MESSAGE(files.front().first < (std::uintmax_t(32) << 20), files.front().second);
    }
}

TEST_CASE("two lab files of 33 MB objects each make a program over 64 MB: refused, named, removed; its lab costs its points") {
    for (const std::string& sandbox : sandboxes()) {
        CAPTURE(sandbox);
        const fs::path folder = submission("big-program");
        copyCourseSolutions(folder);
        for (const char* file : {"ray_cast_integrator.cpp", "sphere_geometry.cpp"}) {
            const fs::path source = folder / "lab3_sphere" / file;
            write(source, readFile(source) + "asm(\".section .rodata\\n.fill 33300000, 1, 1\\n.text\");\n");
        }
        const Graded g = grade(folder, sandbox);
        CHECK_MESSAGE(g.labs.at(3) == expectedLabs({3}).at(3), g.output);
        CHECK(g.labs.at(1) == expectedLabs().at(1));
        const std::regex named(R"(your build made a [0-9.]+ MB program \(raylab-agent-lab3\): over the 64 MB limit)");
        CHECK_MESSAGE(std::regex_search(g.output, named), g.output);
        CHECK_FALSE(fs::exists(kBuild / "bin" / "raylab-agent-lab3"));
    }
}

// The students' tree has no solutions/: no reference lab stands in for a broken one. The grader's
// build of a submission there (buildSubmission in the tree `raylab distribute` writes) gives each lab
// an agent with the labs it uses from the submission and the others' stubs.
TEST_CASE("in the students' tree, a lab that does not build costs that lab and the labs that use it only: the others "
          "keep their points") {
    const fs::path tree = kRoot / "students-tree";
    fs::remove_all(tree);
    fs::create_directories(kRoot); // this case may run before the others made it (it needs none of their files)
    const ProgramRun distributed = runProgram({(binDir() / "raylab").string(), "distribute", tree.string(), "--lang", "en"},
                                              kRoot / "distribute.txt");
    REQUIRE_MESSAGE(distributed.status == 0, distributed.output);
    REQUIRE_FALSE(fs::exists(tree / "solutions"));
    const fs::path folder = submission("students-tree-lab-broken");
    copyCourseSolutions(folder);
    const GradeSetup setup = courseSetup();
    const LabDescription lab = usedLab(setup.labs);
    const fs::path source = folder / lab.id / lab.files().front();
    write(source, "this line is not C++\n" + readFile(source));

    const raylab::grader::Toolchain tools{RAYLAB_CMAKE_COMMAND, RAYLAB_CMAKE_GENERATOR, raylab::grader::findProgram("ccache")};
    const raylab::grader::SubmissionBuild b =
        raylab::grader::buildSubmission(tools, tree, folder, tree / "build", setup.labs);
    CHECK_FALSE(b.isolated);
    const std::vector<int> broken = labAndItsUsers(setup.labs, lab.number);
    CHECK(b.brokenLabs == broken);
    CHECK(b.compilerMessage.find(lab.files().front()) != std::string::npos);
    const GradeResult result = gradeCode(setup, b.agents, b.isolated, b.brokenLabs, b.compilerMessage);
    fs::remove_all(setup.scratch);
    std::map<int, std::string> points;
    for (const LabOutcome& lab : result.labs)
        points[lab.lab] = raylab::formatNumber(lab.points) + " / " + raylab::formatNumber(lab.maxPoints);
    CHECK_MESSAGE(points == expectedLabs(std::set<int>(broken.begin(), broken.end())), failures(result));
}

} // TEST_SUITE
