// Bad submissions get the grade they earned, with a clear reason, and the run goes on.
#include "grading_support.h"
#include "support/files.h"

#include "grader/sandbox/cgroup.h"

#include <fstream>
#include <sstream>

using namespace raylab::test;

namespace {

GradeResult gradeBad(const std::string& id, double wallSeconds = 20.) {
    GradeSetup setup = courseSetup();
    setup.limits.wallSeconds = wallSeconds;
    setup.limits.memoryBytes = 1ull << 30;
    return gradeAgent(setup, "raylab-bad-" + id);
}

void expectCheck(const GradeResult& r, const std::string& name, bool passed, const std::string& says = "") {
    const CheckOutcome* c = findCheck(r, name);
    REQUIRE_MESSAGE(c, name);
    CHECK_MESSAGE(c->passed == passed, name << ": " << c->message);
    if (!says.empty()) CHECK_MESSAGE(c->message.find(says) != std::string::npos, name << ": " << c->message);
}

void expectFigure(const GradeResult& r, const std::string& id, bool passed, const std::string& says = "") {
    const FigureOutcome* f = findFigure(r, id);
    REQUIRE_MESSAGE(f, id);
    CHECK_MESSAGE(f->passed == passed, id << ": " << f->reason);
    if (!says.empty()) CHECK_MESSAGE(f->reason.find(says) != std::string::npos, id << ": " << f->reason);
}

// Run twice by ctest: as this machine confines (bubblewrap when it can start), and with
// RAYLAB_SANDBOX=fallback (an unprivileged user when root). `bubblewrap` false: --no-sandbox.
bool confined(const GradeSetup& setup) { return sandboxKind(setup.limits) != "process group"; }

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// Lab 1 lost points, every item it lost says `says`, and the other labs have all of theirs.
void expectOnlyLab1Lost(const GradeResult& r, const std::string& says) {
    for (const LabOutcome& lab : r.labs) {
        CAPTURE(lab.lab);
        if (lab.lab == 1) CHECK_MESSAGE(lab.points < lab.maxPoints, failures(r));
        else CHECK_MESSAGE(lab.points == lab.maxPoints, failures(r));
    }
    for (const CheckOutcome& c : r.checks)
        if (c.lab == 1 && !c.passed) CHECK_MESSAGE(contains(c.message, says), c.name << ": " << c.message);
    for (const FigureOutcome& f : r.figures)
        if (f.lab == 1 && !f.passed) CHECK_MESSAGE(contains(f.reason, says), f.id << ": " << f.reason);
}

// Whether one of lab 1's items says `says`.
bool lab1Says(const GradeResult& r, const std::string& says) {
    for (const CheckOutcome& c : r.checks)
        if (c.lab == 1 && contains(c.message, says)) return true;
    for (const FigureOutcome& f : r.figures)
        if (f.lab == 1 && contains(f.reason, says)) return true;
    return false;
}

} // namespace

TEST_SUITE("bad submissions") {

TEST_CASE("a crash fails the check that crashed, and the others still run") {
    const GradeResult r = gradeBad("crash");
    expectCheck(r, "centre_and_corners", false, "crash");
    expectCheck(r, "default_viewport", true);
    expectCheck(r, "unit_directions", false, "crash");
    expectFigure(r, "lab3_cosine", true);
}

TEST_CASE("an endless loop is stopped and only its check fails") {
    const GradeResult r = gradeBad("endless_loop", 3.);
    expectCheck(r, "one_pixel_wide", false, "time limit");
    expectCheck(r, "corners_and_middle", true);
    expectFigure(r, "lab1_gradient", true);
    CHECK(r.labs[1].points == r.labs[1].maxPoints);
}

TEST_CASE("an exception fails its check and its figures with the message") {
    const GradeResult r = gradeBad("throws");
    expectCheck(r, "normal", false, "bad: computeNormal throws");
    expectFigure(r, "lab3_cosine", false, "bad: computeNormal throws");
    expectFigure(r, "lab3_flat", true);
}

TEST_CASE("NaN pixels fail the figure and are counted") {
    const GradeResult r = gradeBad("nan");
    expectFigure(r, "lab3_cosine", false, "NaN");
    expectFigure(r, "lab3_flat", true);
}

TEST_CASE("allocating without end is refused, and the other labs are graded") {
    const GradeResult r = gradeBad("allocates");
    expectCheck(r, "corners_and_middle", false);
    expectFigure(r, "lab1_gradient", false);
    expectOnlyLab1Lost(r, ""); // every other lab graded, with all its points
}

TEST_CASE("exit(0) in the middle is no pass") {
    const GradeResult r = gradeBad("exits_early");
    expectCheck(r, "near_side", false, "exited");
    expectFigure(r, "lab3_flat", false);
    expectFigure(r, "lab2_directions", true);
}

TEST_CASE("fake test output on stdout changes nothing") {
    const GradeResult r = gradeBad("fake_output");
    expectCheck(r, "every_pixel", false);
    expectFigure(r, "lab1_gradient", false);
    CHECK(r.labs[0].points == 0.);
}

TEST_CASE("overwriting the references does not help: confined it cannot, in the process group they were read first") {
    const fs::path copy = fs::temp_directory_path() / "raylab-bad-references"; // where the bad code writes
    for (const bool bubblewrap : {false, true}) {
        CAPTURE(bubblewrap);
        fs::remove_all(copy);
        copyReferences(copy);
        const fs::path target = copy / "lab1_gradient.png";
        const auto before = fs::file_size(target);
        GradeSetup setup = courseSetup({copy});
        setup.limits.bubblewrap = bubblewrap;
        const GradeResult r = gradeAgent(setup, "raylab-bad-writes_references");
        CHECK((fs::file_size(target) == before) == confined(setup)); // the attack happened only in the process group
        expectFigure(r, "lab1_gradient", false, "differ from the reference");
    }
    fs::remove_all(copy);
}

TEST_CASE("a lab that re-executes the build's other agents (the reference's, a sibling's) gets nothing from them") {
    const GradeSetup setup = courseSetup();
    const GradeResult r = gradeBad("runs_siblings");
    if (!confined(setup)) {
        MESSAGE("SKIPPED: no sandbox here (" << sandboxKind(setup.limits) << "): the reference's agent would answer");
        return;
    }
    // Under bubblewrap they are not there; under the fallback its user may not run them.
    expectCheck(r, "corners_and_middle", false, "not done yet");
    expectFigure(r, "lab1_gradient", false, "not done yet");
    CHECK(r.labs[0].points == 0.);
    expectFigure(r, "lab3_cosine", true); // the labs it did are graded
}

TEST_CASE("a lab's agent answers its own lab only: lab 2's, asked every lab's items, refuses the others'") {
    const GradeResult r = gradeAgent(courseSetup(), "raylab-agent-lab2"); // built with lab 2 from labs/ here
    expectCheck(r, "corners_and_middle", false, "answers lab 2 only, not lab 1");
    expectFigure(r, "lab3_cosine", false, "answers lab 2 only, not lab 3");
    CHECK(r.labs[0].points == 0.);
    CHECK(r.labs[2].points == 0.);
}

TEST_CASE("a lab that reads the reference solution's file and /etc/passwd at run time shows none of them") {
    const GradeSetup setup = courseSetup();
    const GradeResult r = gradeBad("reads_solutions");
    expectCheck(r, "corners_and_middle", false, "stolen: [");
    expectFigure(r, "lab1_gradient", false, "stolen: [");
    if (!confined(setup)) return; // unconfined, root reads them: what the sandboxes are for
    const std::string said = failures(r);
    CHECK_MESSAGE(said.find("stolen: [] []") != std::string::npos, said); // both files read as empty
    std::istringstream solution(readFile(sourceDir() / "solutions" / "lab1_first_image" / "gradient.cpp"));
    for (std::string line; std::getline(solution, line);)
        if (line.size() >= 30) CHECK_MESSAGE(said.find(line) == std::string::npos, line);
    CHECK(said.find("root:x:0:0") == std::string::npos);
    CHECK(r.labs[0].points == 0.);
}

TEST_CASE("a submission that signals the grader: the grader goes on; in the process group that run earns nothing") {
    for (const bool bubblewrap : {false, true}) {
        CAPTURE(bubblewrap);
        GradeSetup setup = courseSetup();
        setup.limits.wallSeconds = 20.;
        setup.limits.bubblewrap = bubblewrap;
        const GradeResult r = gradeAgent(setup, "raylab-bad-signals_grader"); // and this test is still running
        expectCheck(r, "every_pixel", false);
        if (confined(setup)) { // the signal went to bubblewrap's init, or was refused (another user)
            expectCheck(r, "near_side", true);
        } else { // the grader took it: every result of that run fails, with the reason
            expectCheck(r, "near_side", false, "sent signal 15");
            bool said = false;
            for (const std::string& p : r.problems) said |= p.find("sent signal 15") != std::string::npos;
            CHECK_MESSAGE(said, failures(r));
        }
    }
}

TEST_CASE("a stderr.txt replaced with a link to a file of the grader's: that run earns nothing, no byte of the file is read") {
    const std::string planted = "the grader's own file, which no submission may read back: solutions, /etc/shadow ...\n";
    for (const bool bubblewrap : {false, true}) {
        CAPTURE(bubblewrap);
        GradeSetup setup = courseSetup();
        setup.limits.bubblewrap = bubblewrap;
        fs::create_directories(setup.scratch);
        std::ofstream(setup.scratch / "planted.txt") << planted; // where the link points, beside the agent's folder
        const GradeResult r = gradeAgent(setup, "raylab-bad-links_stderr");
        expectCheck(r, "normal", false, "replaced its output file stderr.txt");
        expectFigure(r, "lab3_cosine", false);
        CHECK(failures(r).find("the grader's own file") == std::string::npos);
        CHECK(r.labs[2].points == 0.);
    }
}

// One student bounded as a whole (docs/grading.md, "Time budgets" and "Limits on a student"): small
// limits here, so that each case ends in seconds; every case ends, and names the limit it hit.

TEST_CASE("answers each within the item's limit spend the lab's time budget: the rest of lab 1 is not run, the other labs are graded") {
    GradeSetup setup = courseSetup();
    // The staller sleeps 2.5 s a call, well within each item's limit: only the budget stops it. The
    // limit leaves the other labs' items room on a sanitizer build of a loaded machine (3 s did not).
    setup.limits.wallSeconds = 15.;
    // Lab 1's reference renders in 0.1 s, so its budget is the floor, 8 s; the other labs' grow with
    // their figures' time, as in a real grading, so that an ASan build on a loaded machine finishes them.
    setup.budget = {80., 8.};
    const GradeResult r = gradeAgent(setup, "raylab-bad-stalls");
    CHECK_MESSAGE(lab1Says(r, "lab 1 used its 8 s"), failures(r));
    for (const LabOutcome& lab : r.labs)
        if (lab.lab != 1) CHECK_MESSAGE(lab.points == lab.maxPoints, lab.lab << failures(r));
}

TEST_CASE("a SIGSTOP uses no CPU but spends wall-clock time: lab 1 ends at its budget, not at the item's limit") {
    GradeSetup setup = courseSetup();
    setup.limits.wallSeconds = 600.; // what would hold the grader if stopped time did not count
    setup.budget = {40., 4.}; // lab 1's budget is the floor, 4 s; the others' as above
    const GradeResult r = gradeAgent(setup, "raylab-bad-stops_itself");
    CHECK_MESSAGE(lab1Says(r, "lab 1 used its 4 s"), failures(r));
    const LabOutcome& lab1 = r.labs.front();
    CHECK(lab1.points == 0.);
    for (const LabOutcome& lab : r.labs)
        if (lab.lab != 1) CHECK_MESSAGE(lab.points == lab.maxPoints, lab.lab << failures(r));
}

TEST_CASE("a fork bomb is stopped at the process limit of all its processes together, and named") {
    GradeSetup setup = courseSetup();
    setup.limits.processes = 64;
    if (!raylab::grader::detail::RunCgroup(setup.limits.processes, setup.limits.memoryBytes).active()) {
        MESSAGE("skipped: no cgroup here (not root, or none delegated), nothing would bound a fork bomb");
        return;
    }
    const GradeResult r = gradeAgent(setup, "raylab-bad-forks");
    expectCheck(r, "normal", false, "too many processes (more than 64");
    expectFigure(r, "lab3_cosine", false, "too many processes");
    CHECK(r.labs[0].points == r.labs[0].maxPoints);
    CHECK(r.labs[1].points == r.labs[1].maxPoints);
}

TEST_CASE("two children that hold 600 MB each, under a limit of 1 GB a process, are stopped at the limit of all its processes") {
    GradeSetup setup = courseSetup();
    setup.limits.memoryBytes = 1ull << 30;
    if (!raylab::grader::detail::RunCgroup(setup.limits.processes, setup.limits.memoryBytes).active()) {
        MESSAGE("skipped: no cgroup here (not root, or none delegated), memory is limited per process only");
        return;
    }
    const GradeResult r = gradeAgent(setup, "raylab-bad-holds_memory");
    expectOnlyLab1Lost(r, "used more than 1 GB of memory");
}

TEST_CASE("filling its working folder, or /tmp, is stopped at the disk limit, and named") {
    for (const std::string id : {"fills_scratch", "fills_tmp"}) {
        CAPTURE(id);
        GradeSetup setup = courseSetup();
        if (id == "fills_tmp" && !confined(setup)) { // the process group has the machine's /tmp
            MESSAGE("skipped: not confined here, /tmp is the machine's");
            continue;
        }
        setup.limits.diskBytes = 32ull << 20;
        const GradeResult r = gradeAgent(setup, "raylab-bad-" + id);
        const std::string kind = sandboxKind(setup.limits);
        if (id == "fills_tmp" && kind.rfind("unprivileged user", 0) == 0 && kind.find("no Landlock") == std::string::npos) {
            // The fallback with Landlock has no /tmp at all: not a byte written there, nothing to stop.
            CHECK_FALSE(fs::exists("/tmp/fill-0"));
            for (const LabOutcome& lab : r.labs) CHECK_MESSAGE(lab.points == lab.maxPoints, failures(r));
            continue;
        }
        expectOnlyLab1Lost(r, "wrote more than 32 MB");
    }
}

} // TEST_SUITE
