// raylab grade, raylab grade-class: the grader's commands (framework/grader/ does the work).
#include "build_info.h"
#include "commands.h"

#include "grader/class_page/gradebook.h"
#include "grader/class_page/student_outcome.h"
#include "grader/course/autograder.h"
#include "grader/course/class_run.h"
#include "grader/judge/grade.h"
#include "grader/course/grade_reports.h"
#include "grader/course/run_scratch.h"
#include "grader/sandbox/process.h"
#include "grader/sandbox/sandbox.h"
#include "grader/course/submission.h"
#include "grader/course/submission_copy.h"
#include "src/messages.h"
#include "src/text.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
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
    std::string item; // one check (its name) or figure (its id) alone
    bool noSandbox = false; // grade-class: grade without bubblewrap, as asked
    std::string roster;     // grade-class: the students' ids for the gradebook files
};

// raylab grade's exit status when no graded lab has anything written yet (every item reached its
// lab's own stubs): the students' tree's ctest reports such a lab as skipped, not failed.
constexpr int kNothingWrittenStatus = 3;

// Names the scratch folders that runs killed with SIGKILL left and that `scratch` removed as it was
// made (a live run's never: its lock is held); `command` says whose they were.
void noteRemovedScratch(const RunScratch& scratch, const std::string& command) {
    for (const fs::path& removed : scratch.removedAtStart())
        std::printf("%s\n", tr("grade.abandoned_scratch_removed", {{"folder", printablePath(removed)}, {"command", command}}).c_str());
}

GradeSetup setupFor(const GradeOptions& o, const Context& context, const fs::path& scratch) {
    GradeSetup setup = loadGradeSetup(referenceFolders(o.references), labsFolder(), context.scenes, scratch);
    if (o.lab != 0 && setup.labs.lab(o.lab) == nullptr)
        throw std::invalid_argument(tr("grade.no_such_lab", {{"lab", std::to_string(o.lab)}, {"labs", labList(setup.labs)}}));
    setup.limits.wallSeconds = o.timeout;
    setup.limits.bubblewrap = !o.noSandbox;
    setup.threads = context.threads;
    return setup;
}

// The students of a class build the same framework files: through ccache when it is installed
// (CCACHE_DISABLE=1 turns it off). A student's own build is incremental already, and keeps the
// compiler's paths as they are.
Toolchain toolchain(bool forClass) {
    return Toolchain{RAYLAB_CMAKE_COMMAND, RAYLAB_CMAKE_GENERATOR, forClass ? findProgram("ccache") : fs::path()};
}

// --images: a line per figure; 0 only when every figure found passes.
int gradeImageFolder(const GradeOptions& o, const Context& context) {
    const RunScratch scratch("images"); // removed at its end, even on an exception
    noteRemovedScratch(scratch, "grade --images");
    const GradeSetup setup = setupFor(o, context, scratch.path());
    GradeResult result = gradeImages(setup, o.images);
    result.title = "raylab grade --images " + printablePath(o.images);
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
                                                   {"total", std::to_string(result.figures.size())},
                                                   {"failed", std::to_string(failed)},
                                                   {"missing", std::to_string(result.figures.size() - std::size_t(found))},
                                                   {"report", printablePath(fs::path(o.report) / "index.html")}})
                            .c_str());
    return found > 0 && failed == 0 ? 0 : 1;
}

// Where a submission is copied and its build's output written: in its build folder, or, in a class,
// whose build folder every student shares, in the student's own folder.
struct SubmissionPlaces {
    fs::path buildDir, copy, log;
};

// Grades one body of code (this build's labs, a submission, or given agents) into a report.
GradeResult gradeCodeOnce(const GradeOptions& o, const GradeSetup& setup, const Toolchain& tools,
                          const SubmissionPlaces& places, std::string title) {
    const fs::path& buildDir = places.buildDir;
    std::vector<AgentPlan> agents;
    bool isolated = false;
    std::vector<int> unbuilt;
    std::string message, ignored;
    if (!o.agents.empty()) {
        for (const std::string& a : o.agents) agents.push_back({fs::absolute(a), 0});
    } else if (!o.labs.empty()) {
        // The grader's own copy of the lab files, wherever the submission holds them: CMake builds that alone.
        const SubmissionCopy copy = copySubmission(o.labs, setup.labs, places.copy);
        if (copy.labs.empty()) {
            GradeResult result = gradeWithoutLabFiles(setup, copy);
            result.title = std::move(title);
            return result;
        }
        ignored = ignoredFilesNote(copy, setup.labs);
        std::printf("%s\n", tr("grade.building", {{"labs", printablePath(o.labs)}, {"folder", printablePath(buildDir)}}).c_str());
        std::fflush(stdout);
        const SubmissionBuild b =
            buildSubmission(tools, build::kSourceDir, copy.folder, buildDir, setup.labs, places.log);
        agents = b.agents;
        isolated = b.isolated;
        unbuilt = b.brokenLabs;
        message = b.compilerMessage;
    } else {
        BuiltAgents built = agentsOfThisBuild(setup.labs, o.lab != 0 ? std::vector<int>{o.lab} : setup.labs.numbers());
        agents = std::move(built.agents);
        isolated = built.isolated;
        unbuilt = std::move(built.unbuilt);
        message = std::move(built.message);
        if (agents.empty() && unbuilt.empty())
            throw std::runtime_error(tr("grade.no_agent", {{"folder", build::kBinaryDir}}));
    }
    if (o.lab != 0) { // one lab: its own agent, or the cumulative agent asked for that lab only
        std::erase_if(agents, [&](const AgentPlan& a) { return a.lab != 0 && a.lab != o.lab; });
        for (AgentPlan& a : agents) a.lab = o.lab;
        std::erase_if(unbuilt, [&](int lab) { return lab != o.lab; });
    }
    GradeResult result = gradeCode(setup, agents, isolated, unbuilt, message);
    if (!ignored.empty()) result.problems.push_back(ignored);
    result.title = std::move(title);
    return result;
}

int gradeLabs(GradeOptions o, const Context& context) {
    // labs/ as it is now: this program (the checks, their messages) and the agents rebuilt when a file
    // they are built from changed (a lab, its grading folder, the framework); with --lab N, that lab's
    // agent alone. A lab that does not compile costs that lab (and those that use it): the others'
    // agents are built all the same, and graded.
    if (o.labs.empty() && o.agents.empty()) ensureFreshAgents(context, o.lab);
    const RunScratch scratch("grade"); // removed at its end, even on an exception
    noteRemovedScratch(scratch, "grade");
    const GradeSetup setup = setupFor(o, context, scratch.path());
    if (!o.item.empty()) o.lab = labOfItem(setup.labs, o.item); // its lab is graded, the item alone kept
    const fs::path buildDir = o.buildDir.empty() ? fs::path("out/grade-build") : fs::path(o.buildDir);
    GradeResult result = gradeCodeOnce(o, setup, toolchain(false), {buildDir, buildDir / "submission", {}},
                                       "raylab grade " + (o.labs.empty() ? std::string("(labs/)") : printablePath(o.labs)));
    if (!o.item.empty()) result = onlyItem(result, o.item);
    std::printf("%s", terminalSummary(result).c_str());
    writeReports(result, setup.references, o.report);
    std::printf("%s\n", tr("grade.report_written", {{"report", printablePath(fs::path(o.report) / "index.html")}}).c_str());
    if (result.allPassed()) return 0;
    const bool nothingWritten = std::all_of(result.labs.begin(), result.labs.end(),
                                            [](const LabOutcome& l) { return l.notStarted || l.maxPoints == 0.; });
    return nothingWritten ? kNothingWrittenStatus : 1;
}

// A student's row of grades.csv: points per lab, the total, and the first lines of the problems.
StudentRecord classRecord(const std::string& name, const GradeResult& result) {
    StudentRecord record{name, {}};
    const auto number = [](double v) {
        std::ostringstream text;
        text << v;
        return text.str();
    };
    for (const LabOutcome& lab : result.labs) record.cells.emplace_back("lab" + std::to_string(lab.lab), number(lab.points));
    std::string problems;
    for (const std::string& p : result.problems) problems += (problems.empty() ? "" : " | ") + problemSummary(p);
    record.cells.emplace_back("total", number(result.score()));
    record.cells.emplace_back("max", number(result.maxScore()));
    record.cells.emplace_back("problems", problems);
    return record;
}

// The reference folders, as a result's settings name them.
std::string referencesShown(const std::string& given) {
    std::string shown;
    for (const fs::path& folder : referenceFolders(given))
        shown += (shown.empty() ? "" : " ") + fs::absolute(folder).lexically_normal().string();
    return shown;
}

// What makes a student's result: another value of any of them and the student is graded again.
Settings resultSettings(const GradeOptions& o, const GradeSetup& setup) {
    std::string agents;
    for (const std::string& a : o.agents) agents += (agents.empty() ? "" : " ") + fs::absolute(a).string();
    std::ostringstream timeout;
    timeout << o.timeout;
    return {{"grader", std::string("raylab ") + build::kVersion},
            {"labs", o.lab == 0 ? "all" : std::to_string(o.lab)},
            {"timeout", timeout.str()},
            {"sandbox", sandboxKind(setup.limits)},
            {"references", referencesShown(o.references)},
            {"agents", agents.empty() ? "built from each submission" : agents}};
}

// On Linux a class is graded under bubblewrap, or its fallback as root (an unprivileged user), or
// confined by neither only when --no-sandbox says so: the students' code could otherwise read the
// references and each other's folders.
void requireBubblewrapForClass(const GradeOptions& o) {
#ifdef __linux__
    if (o.noSandbox) return;
    if (sandboxKind(SandboxLimits{}) != "process group") return;
    const std::string missing = bubblewrapMissing();
    const std::string why = missing.empty() ? tr("sandbox.none_asked") : missing;
    throw std::runtime_error(tr("sandbox.class_needs_bubblewrap", {{"why", why}}));
#else
    (void)o;
#endif
}

int gradeClass(ClassRunOptions run, const GradeOptions& o, const Context& context) {
    requireBubblewrapForClass(o);
    const std::vector<RosterEntry> roster = classRoster(o.roster); // a wrong roster stops before anyone is graded
    // The compiler's guard (raylab-build-guard, started by CMake) reads it: not confined either.
#if defined(__unix__) || defined(__APPLE__)
    if (o.noSandbox) setenv("RAYLAB_SANDBOX", "none", 1);
#endif
    const StopSignals stopSignals; // a stop from here on ends the run cleanly, scratch removal included
    const RunScratch scratch("class"); // removed at its end, even on an exception
    noteRemovedScratch(scratch, "grade-class");
    run.runOnlyDescriptors.push_back(scratch.lockDescriptor());
    const GradeSetup setup = setupFor(o, context, scratch.path());
    run.madeBy = resultSettings(o, setup);
    // One build folder for the class: the framework and the reference labs are compiled once, before
    // the first student; each student then costs their lab files and the links.
    const fs::path classBuild = o.buildDir.empty() ? run.out / "build" : fs::path(o.buildDir);
    if (o.agents.empty())
        run.beforeFirstStudent = [&] {
            const fs::path log = classBuild / "grading-kit.log";
            std::printf("%s\n", tr("grade.building_class_kit", {{"folder", printablePath(classBuild)}}).c_str());
            std::fflush(stdout);
            if (!buildGradingKit(toolchain(true), build::kSourceDir, classBuild, log))
                std::printf("%s\n", tr("grade.class_kit_failed", {{"log", printablePath(log)}}).c_str());
        };
    run.afterLastStudent = [&] { remakeClassPage(run.out, roster); };
    const int status = runClass(run, [&](const StudentWork& work) {
        GradeOptions student = o;
        student.labs = work.submission.string();
        const std::string title = "raylab grade " + printableName(work.name);
        GradeResult result;
        try {
            result = gradeCodeOnce(student, setup, toolchain(true),
                                   {classBuild, work.folder / "submission", work.folder / "build.log"}, title);
        } catch (const std::exception& e) { // one student's trouble never stops the class; a full disk does
            if (isDiskFull(e)) throw;
            result = gradeBuildFailure(setup, e.what());
            result.title = title;
        }
        writeReports(result, setup.references, work.folder / "report");
        writeStudentOutcome(outcomeOf(result), work.folder / "outcome.json"); // before result.json: the class page's
        std::printf("%-20s %g / %g\n", printableName(work.name).c_str(), result.score(), result.maxScore());
        return classRecord(work.name, result);
    });
    return status;
}

void addCommonOptions(CLI::App* command, GradeOptions& o) {
    command->add_option("--references", o.references, tr("cli.grade_references"));
    command->add_option("--timeout", o.timeout, tr("cli.grade_timeout"))
        ->check(positiveSeconds());
    command->add_option("--build-dir", o.buildDir, tr("cli.grade_build_dir"));
}

} // namespace

void addGradeCommands(CLI::App& app, Context& context) {
    auto o = std::make_shared<GradeOptions>();
    CLI::App* grade = app.add_subcommand("grade", tr("cli.grade"));
    grade->add_option("--labs", o->labs, tr("cli.grade_labs"))->check(CLI::ExistingDirectory);
    grade->add_option("--images", o->images, tr("cli.grade_images"));
    grade->add_option("--report", o->report, tr("cli.grade_report"));
    grade->add_option("--lab", o->lab, tr("cli.grade_lab"))->check(CLI::PositiveNumber);
    grade->add_option("--item", o->item, tr("cli.grade_item"));
    grade->add_option("--agent", o->agents, tr("cli.grade_agent"))->group("");
    addCommonOptions(grade, *o);
    context.addRenderOptions(grade);
    grade->callback([&context, o] {
        context.exitStatus = o->images.empty() ? gradeLabs(*o, context) : gradeImageFolder(*o, context);
    });

    auto classOptions = std::make_shared<GradeOptions>();
    auto run = std::make_shared<ClassRunOptions>();
    run->out = "out/class";
    CLI::App* gradeClassCommand = app.add_subcommand("grade-class", tr("cli.grade_class"));
    gradeClassCommand->add_option(tr("cli.type.DIR"), run->classFolder, tr("cli.grade_class_dir"))->required()->check(CLI::ExistingDirectory);
    gradeClassCommand->add_option("--out", run->out, tr("cli.grade_class_out"));
    gradeClassCommand->add_flag("--wait", run->wait, tr("cli.grade_class_wait"));
    gradeClassCommand->add_flag("--no-sandbox", classOptions->noSandbox,
                                tr("cli.grade_class_no_sandbox"));
    gradeClassCommand->add_option("--lab", classOptions->lab, tr("cli.grade_lab"))->check(CLI::PositiveNumber);
    gradeClassCommand->add_option("--roster", classOptions->roster, tr("cli.grade_class_roster"))->check(CLI::ExistingFile);
    gradeClassCommand->add_option("--agent", classOptions->agents, tr("cli.grade_class_agent"))
        ->group("");
    addCommonOptions(gradeClassCommand, *classOptions);
    context.addRenderOptions(gradeClassCommand);
    gradeClassCommand->callback([&context, classOptions, run] { context.exitStatus = gradeClass(*run, *classOptions, context); });
}

} // namespace raylab::cli
