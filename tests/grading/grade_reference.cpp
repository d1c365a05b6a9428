// The reference solutions pass, with any thread count and seed; the references are what the
// solutions make; the stubs get zero and are told which function to write.
#include "grading_support.h"
#include "support/course.h"

#include "grader/judge/checks/checks.h"

#include <cmath>
#include <set>

using namespace raylab::test;

TEST_SUITE("grade reference") {

TEST_CASE("the reference solutions get every point, on 1 or 2 threads and several seeds") {
    for (const auto& [threads, seed] : {std::pair{1, -1LL}, std::pair{2, 12345LL}, std::pair{2, 777LL}}) {
        GradeSetup setup = courseSetup();
        setup.threads = threads;
        setup.seed = seed;
        const GradeResult r = gradeAgent(setup, "raylab-agent-reference");
        CHECK_MESSAGE(r.allPassed(), "threads " << threads << ", seed " << seed << failures(r));
        CHECK(r.score() == r.maxScore());
        std::size_t describedChecks = 0;
        for (const LabDescription& lab : setup.labs.labs) describedChecks += lab.checks.size();
        CHECK(r.checks.size() == describedChecks);
        CHECK(r.figures.size() == setup.references.figures.size());
    }
}

TEST_CASE("every check the grader runs is in its lab's description, and the other way round") {
    const GradeSetup setup = courseSetup(); // loadGradeSetup refuses a mismatch (unit_points.cpp shows it)
    std::set<std::string> listed;
    for (const FunctionCheck& c : functionChecks(setup.labs, 1)) {
        listed.insert(c.id);
        const LabDescription* lab = setup.labs.lab(c.lab);
        REQUIRE_MESSAGE((lab != nullptr && lab->check(c.id) != nullptr), "lab " << c.lab << ": \"" << c.id << "\"");
        CHECK(c.points == lab->check(c.id)->points);
    }
    for (const LabDescription& lab : setup.labs.labs)
        for (const LabCheck& check : lab.checks)
            CHECK_MESSAGE(listed.count(check.id), lab.file.string() << " names \"" << check.id << "\", which no check has");
}

TEST_CASE("the stubs of labs/ get zero, each check saying what to write") {
    GradeSetup setup = courseSetup();
    std::vector<AgentPlan> agents;
    for (int lab : setup.labs.numbers()) agents.push_back({binDir() / ("raylab-agent-lab" + std::to_string(lab)), lab});
    const GradeResult r = gradeCode(setup, agents, true);
    fs::remove_all(setup.scratch);
    CHECK(r.score() == 0.);
    const CheckOutcome* c = findCheck(r, "unit_directions");
    REQUIRE(c);
    CHECK(c->message.find("lab 2 not done yet: write PerspectiveCamera::updateViewport") != std::string::npos);
    const FigureOutcome* f = findFigure(r, "lab3_cosine");
    REQUIRE(f);
    CHECK(f->reason.find("lab 3 not done yet") != std::string::npos);
    CHECK(r.labs[2].notes.front().find("other labs came from the reference") != std::string::npos);
    // Nothing of any lab is written: each says so, last.
    for (const LabOutcome& lab : r.labs) {
        CHECK(lab.notStarted);
        CHECK(lab.notes.back() == "nothing of lab " + std::to_string(lab.lab) +
                                      " is written yet: each of its checks and figures reached a stub (its own or an earlier lab's)");
    }
}

} // TEST_SUITE

TEST_SUITE("grade reference: lab 5") { // skipped where the course does not hand lab 5 out

// The course's own statistical reference rejects the broken renders of the issue: blurred, and
// a biased average (sum / (N + 1)); the correct render itself passes.
TEST_CASE("lab5_antialiased: blurred and biased versions of a correct render fail") {
    if (!labInCourse(sourceDir() / "labs", 5)) return;
    const GradeSetup setup = courseSetup();
    const FigureReference* lab5 = setup.references.find("lab5_antialiased");
    REQUIRE(lab5);
    REQUIRE(lab5->stats);
    const raylab::Image8& correct = lab5->image;
    CHECK(compareImage(*lab5, correct).passed);

    raylab::Image8 blurred = correct, biased = correct;
    for (int j = 1; j + 1 < correct.height; ++j)
        for (int i = 1; i + 1 < correct.width; ++i)
            for (int c = 0; c < 3; ++c) {
                int sum = 0;
                for (int y = -1; y <= 1; ++y)
                    for (int x = -1; x <= 1; ++x) sum += correct.pixel(i + x, j + y)[c];
                blurred.rgb[3 * (std::size_t(j) * correct.width + i) + c] = std::uint8_t((sum + 4) / 9);
            }
    for (std::uint8_t& v : biased.rgb) v = std::uint8_t(std::lround(v * 32. / 33.));
    const ImageVerdict b = compareImage(*lab5, blurred), s = compareImage(*lab5, biased);
    CHECK_FALSE(b.passed);
    CHECK_FALSE(s.passed);
    CHECK(s.reason.find("biased") != std::string::npos);
    MESSAGE("blurred 3 x 3: " << b.reason);
    MESSAGE("sum / (N + 1): " << s.reason);
}

} // TEST_SUITE

TEST_SUITE("grade reference") {

TEST_CASE("without the reference, grading is cumulative and names the earlier lab to fix first") {
    GradeSetup setup = courseSetup();
    const GradeResult r = gradeCode(setup, {{binDir() / "raylab-agent", 0}}, false); // labs/: all stubs
    fs::remove_all(setup.scratch);
    REQUIRE(r.labs.size() == setup.labs.labs.size());
    // Each lab's last note: nothing of it is written yet (all stubs).
    CHECK(r.labs[0].notes.size() == 1);
    REQUIRE_FALSE(r.labs[2].notes.empty());
    CHECK(r.labs[2].notes.front() == "lab 3 uses lab 2, which has failures: fix lab 2 first");
    // Labs 2 and 4 use each other (a lab 2 check builds a lookAt camera): said once, from the later lab.
    CHECK(r.labs[1].notes.size() == 1);
}

} // TEST_SUITE

TEST_SUITE("grade reference: lab 4") { // skipped where the course does not hand lab 4 out

TEST_CASE("without the reference, lab 4 names the earlier labs to fix first, and not started") {
    if (!labInCourse(sourceDir() / "labs", 4)) return;
    GradeSetup setup = courseSetup();
    const GradeResult r = gradeCode(setup, {{binDir() / "raylab-agent", 0}}, false); // labs/: all stubs
    fs::remove_all(setup.scratch);
    const auto lab4 = std::find_if(r.labs.begin(), r.labs.end(), [](const LabOutcome& lab) { return lab.lab == 4; });
    REQUIRE(lab4 != r.labs.end());
    CHECK(lab4->notes.size() == 3); // labs 2 and 3, and not started
}

} // TEST_SUITE

// Issue 11: a lab is graded on its own code. A student who did lab N alone (every other lab the
// handed-out stub) is graded cumulatively as in the students' tree; with the earlier labs from the
// reference (solutions/ present), lab N gets every point: no check of a lab needs a later lab.
TEST_SUITE("grade reference") {

TEST_CASE("each lab alone, the other labs stubs: its own points, and no circular advice") {
    const GradeSetup setup = courseSetup();
    for (int lab : setup.labs.numbers()) {
        CAPTURE(lab);
        const GradeResult alone = gradeAgent(courseSetup(), "raylab-alone-lab" + std::to_string(lab));
        const GradeResult overReference =
            gradeAgent(courseSetup(), "raylab-alone-over-reference-lab" + std::to_string(lab));
        const LabDescription& description = *setup.labs.lab(lab);
        for (const LabOutcome& outcome : overReference.labs)
            if (outcome.lab == lab)
                CHECK_MESSAGE(outcome.points == outcome.maxPoints, "over the reference" << failures(overReference));
        // With the other labs stubs, only what uses an earlier lab may fail, and then the note says so.
        for (const CheckOutcome& c : alone.checks)
            if (c.lab == lab && !c.passed)
                CHECK_MESSAGE(!description.check(c.name)->uses.empty(), c.name << ": " << c.message);
        for (const FigureOutcome& f : alone.figures)
            if (f.lab == lab && !f.passed)
                CHECK_MESSAGE(!description.figure(f.id)->uses.empty(), f.id << ": " << f.reason);
        for (const LabOutcome& outcome : alone.labs) {
            if (outcome.lab == lab && description.uses.empty())
                CHECK_MESSAGE(outcome.points == outcome.maxPoints, failures(alone));
            for (const std::string& note : outcome.notes) {
                CAPTURE(note);
                // "lab N uses lab K ... fix lab K first": always an earlier lab, never the correct one.
                CHECK(note.find("fix lab " + std::to_string(lab) + " first") == std::string::npos);
                for (int later = outcome.lab + 1; later <= 9; ++later)
                    CHECK(note.find("fix lab " + std::to_string(later) + " first") == std::string::npos);
            }
        }
    }
}

} // TEST_SUITE
