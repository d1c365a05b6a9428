// raylab grade, raylab grade-class: the grader's commands (framework/grader/ does the work).
#include "build_info.h"
#include "commands.h"

#include "grader/grade.h"
#include "grader/report.h"
#include "grader/submission.h"
#include "raylab/messages.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <random>
#include <set>
#include <sstream>

namespace raylab::cli {

namespace {

namespace fs = std::filesystem;
using namespace raylab::grader;

struct GradeOptions {
    std::string labs, images, report = "out/report", references, buildDir;
    std::vector<std::string> agents; // expert: grade these agent programs (each runs every lab)
    double timeout = 180.;
    int lab = 0; // 0: every lab
};

// A fresh folder of our own for the agents' files.
fs::path scratchFolder(const std::string& what) {
    std::random_device random;
    const fs::path folder = fs::temp_directory_path() / ("raylab-" + what + "-" + std::to_string(random()));
    fs::create_directories(folder);
    return folder;
}

std::string labList(const LabCatalog& catalog) {
    std::string list;
    for (int n : catalog.numbers()) list += " " + std::to_string(n);
    return tr("grade.labs_are", {{"labs", list}});
}

GradeSetup setupFor(const GradeOptions& o, const Context& context, const fs::path& scratch) {
    GradeSetup setup = loadGradeSetup(o.references.empty() ? referencesFolder() : fs::path(o.references), labsFolder(),
                                      context.scenes, scratch);
    if (o.lab != 0 && setup.labs.lab(o.lab) == nullptr) {
        fs::remove_all(scratch);
        throw std::invalid_argument(tr("grade.no_such_lab", {{"lab", std::to_string(o.lab)}, {"labs", labList(setup.labs)}}));
    }
    setup.limits.wallSeconds = o.timeout;
    setup.threads = context.threads;
    return setup;
}

Toolchain toolchain() { return Toolchain{RAYLAB_CMAKE_COMMAND, RAYLAB_CMAKE_GENERATOR}; }

// --images: a line per figure; 0 only when every figure found passes.
int gradeImageFolder(const GradeOptions& o, const Context& context) {
    const fs::path scratch = scratchFolder("images");
    const GradeSetup setup = setupFor(o, context, scratch);
    GradeResult result = gradeImages(setup, o.images);
    result.title = "raylab grade --images " + o.images;
    int found = 0, failed = 0;
    for (const FigureOutcome& f : result.figures) {
        std::printf("%s  %-24s %s\n", tr(f.passed ? "report.pass" : "report.fail").c_str(), f.id.c_str(), f.reason.c_str());
        if (!f.diagnosis.empty()) std::printf("      %-24s %s\n", "", f.diagnosis.c_str());
        if (f.found) ++found;
        if (f.found && !f.passed) ++failed;
    }
    for (const std::string& p : result.problems) std::printf("%s\n", tr("grade.note", {{"note", p}}).c_str());
    writeReports(result, setup.references, o.report);
    std::printf("%s\n", tr("grade.images_summary", {{"found", std::to_string(found)},
                                                   {"failed", std::to_string(failed)},
                                                   {"report", o.report + "/index.html"}})
                            .c_str());
    fs::remove_all(scratch);
    return found > 0 && failed == 0 ? 0 : 1;
}

// Grades one body of code (this build's labs, a submission, or given agents) into a report.
GradeResult gradeCodeOnce(const GradeOptions& o, const GradeSetup& setup, const fs::path& buildDir, std::string title) {
    std::vector<AgentPlan> agents;
    bool isolated = false;
    std::vector<int> unbuilt;
    std::string message;
    if (!o.agents.empty()) {
        for (const std::string& a : o.agents) agents.push_back({fs::absolute(a), 0});
    } else if (!o.labs.empty()) {
        std::printf("%s\n", tr("grade.building", {{"labs", o.labs}, {"folder", buildDir.string()}}).c_str());
        std::fflush(stdout);
        const SubmissionBuild b =
            buildSubmission(toolchain(), build::kSourceDir, submissionLabsFolder(o.labs), buildDir, setup.labs.numbers());
        agents = b.agents;
        isolated = b.isolated;
        unbuilt = b.brokenLabs;
        message = b.compilerMessage;
    } else {
        agents = findAgents(build::kBinaryDir, setup.labs.numbers(), isolated);
        if (agents.empty())
            throw std::runtime_error(tr("grade.no_agent", {{"folder", build::kBinaryDir}}));
    }
    if (o.lab != 0) { // one lab: its own agent, or the cumulative agent asked for that lab only
        std::erase_if(agents, [&](const AgentPlan& a) { return a.lab != 0 && a.lab != o.lab; });
        for (AgentPlan& a : agents) a.lab = o.lab;
        std::erase_if(unbuilt, [&](int lab) { return lab != o.lab; });
    }
    GradeResult result = gradeCode(setup, agents, isolated, unbuilt, message);
    result.title = std::move(title);
    return result;
}

int gradeLabs(const GradeOptions& o, const Context& context) {
    const fs::path scratch = scratchFolder("grade");
    const GradeSetup setup = setupFor(o, context, scratch);
    const fs::path buildDir = o.buildDir.empty() ? fs::path("out/grade-build") : fs::path(o.buildDir);
    const GradeResult result =
        gradeCodeOnce(o, setup, buildDir, "raylab grade " + (o.labs.empty() ? std::string("(labs/)") : o.labs));
    std::printf("%s", terminalSummary(result).c_str());
    writeReports(result, setup.references, o.report);
    std::printf("%s\n", tr("grade.report_written", {{"report", o.report + "/index.html"}}).c_str());
    fs::remove_all(scratch);
    return result.allPassed() ? 0 : 1;
}

// The students already in the CSV: a class run that stopped resumes after them.
std::set<std::string> gradedStudents(const fs::path& csv) {
    std::set<std::string> done;
    std::ifstream in(csv);
    std::string line;
    std::getline(in, line); // header
    while (std::getline(in, line))
        if (!line.empty()) done.insert(line.substr(0, line.find(',')));
    return done;
}

std::string csvField(std::string s) {
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string out = "\"";
    for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

int gradeClass(const std::string& classDir, const std::string& outDir, GradeOptions o, const Context& context) {
    const fs::path out = outDir.empty() ? fs::path("out/class") : fs::path(outDir);
    fs::create_directories(out);
    const fs::path csv = out / "grades.csv";
    const std::set<std::string> done = gradedStudents(csv);
    const fs::path scratch = scratchFolder("class");
    const GradeSetup setup = setupFor(o, context, scratch);
    if (!fs::exists(csv)) {
        std::ofstream header(csv);
        header << "student";
        for (const LabDescription& lab : setup.labs.labs) header << ",lab" << lab.number;
        header << ",total,max,problems\n";
    }
    std::vector<fs::path> students;
    for (const auto& entry : fs::directory_iterator(classDir))
        if (entry.is_directory()) students.push_back(entry.path());
    std::sort(students.begin(), students.end());
    for (const fs::path& student : students) {
        const std::string name = student.filename().string();
        if (done.count(name)) {
            std::printf("%-20s already graded (in %s)\n", name.c_str(), csv.string().c_str());
            continue;
        }
        o.labs = student.string();
        GradeResult result;
        try {
            result = gradeCodeOnce(o, setup, o.buildDir.empty() ? out / "build" : fs::path(o.buildDir), "raylab grade " + name);
        } catch (const std::exception& e) { // one student's trouble never stops the class
            result = gradeBuildFailure(setup, e.what());
            result.title = "raylab grade " + name;
        }
        writeReports(result, setup.references, out / name);
        std::ostringstream row;
        row << csvField(name);
        for (const LabOutcome& lab : result.labs) row << "," << lab.points;
        std::string problems;
        for (const std::string& p : result.problems) { // its first two lines: what, and the first error
            const std::size_t second = p.find('\n', p.find('\n') + 1);
            problems += (problems.empty() ? "" : " | ") + p.substr(0, std::min<std::size_t>(second, 300));
        }
        row << "," << result.score() << "," << result.maxScore() << "," << csvField(problems) << "\n";
        std::ofstream(csv, std::ios::app) << row.str() << std::flush; // a row a student: nothing lost on a stop
        std::printf("%-20s %g / %g\n", name.c_str(), result.score(), result.maxScore());
        std::fflush(stdout);
    }
    fs::remove_all(scratch);
    std::printf("grades: %s, reports: %s/<student>/index.html\n", csv.string().c_str(), out.string().c_str());
    return 0;
}

void addCommonOptions(CLI::App* command, GradeOptions& o) {
    command->add_option("--references", o.references, "the reference folder (default: framework/grader/data/references)");
    command->add_option("--timeout", o.timeout, "seconds a check or figure may run before it is stopped");
    command->add_option("--build-dir", o.buildDir, "where submissions are built");
}

} // namespace

void addGradeCommands(CLI::App& app, Context& context) {
    auto o = std::make_shared<GradeOptions>();
    CLI::App* grade = app.add_subcommand("grade", "grade your labs (or a submission, or pictures) against the references");
    grade->add_option("--labs", o->labs, "a submission: a copy of labs/ to build and grade")->check(CLI::ExistingDirectory);
    grade->add_option("--images", o->images, "grade pictures DIR/<figure id>.png, no code");
    grade->add_option("--report", o->report, "where the reports go (default: out/report)");
    grade->add_option("--lab", o->lab, "grade this lab only (its number)")->check(CLI::PositiveNumber);
    grade->add_option("--agent", o->agents, "expert: grade this agent program (all labs)")->group("");
    addCommonOptions(grade, *o);
    context.addRenderOptions(grade);
    grade->callback([&context, o] {
        context.exitStatus = o->images.empty() ? gradeLabs(*o, context) : gradeImageFolder(*o, context);
    });

    auto classDir = std::make_shared<std::string>();
    auto outDir = std::make_shared<std::string>();
    CLI::App* gradeClassCommand = app.add_subcommand(
        "grade-class", "grade every submission of DIR (one folder per student) into a CSV and reports; resumable");
    gradeClassCommand->add_option("DIR", *classDir, "one folder per student")->required()->check(CLI::ExistingDirectory);
    gradeClassCommand->add_option("--out", *outDir, "grades.csv and the reports (default: out/class)");
    addCommonOptions(gradeClassCommand, *o);
    context.addRenderOptions(gradeClassCommand);
    gradeClassCommand->callback([&context, o, classDir, outDir] {
        context.exitStatus = gradeClass(*classDir, *outDir, *o, context);
    });
}

} // namespace raylab::cli
