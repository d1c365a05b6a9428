// The function checks see what the figures cannot: lookAt mistakes that only show when `up` is not
// perpendicular to the view direction, and a viewport left stale by the lookAt constructor (the
// reference generateRay never reads it, so the figures pass): lab 4's, a suite of its own, skipped where
// the course does not hand lab 4 out.
#include "grading_support.h"
#include "support/course.h"

using namespace raylab::test;

namespace {

const CheckOutcome& check(const GradeResult& r, const std::string& name) {
    const CheckOutcome* c = findCheck(r, name);
    REQUIRE_MESSAGE(c, name);
    return *c;
}

} // namespace

TEST_SUITE("checks") {

    TEST_CASE("an inward normal: computeNormal is told to point outwards, Li is sent to computeNormal, not told its own formula") {
        const GradeResult r = gradeAgent(courseSetup(), "raylab-bad-normal_inwards");
        const CheckOutcome& normal = check(r, "normal");
        CHECK_FALSE(normal.passed);
        CHECK_MESSAGE(normal.message.find("from the centre outwards") != std::string::npos, normal.message);
        CHECK_MESSAGE(normal.message.find("divide by the radius") == std::string::npos, normal.message);
        const CheckOutcome& cosine = check(r, "cosine");
        CHECK_FALSE(cosine.passed);
        CHECK_MESSAGE(cosine.message.find("fix computeNormal") != std::string::npos, cosine.message);
        CHECK_MESSAGE(cosine.message.find("with the true normal") == std::string::npos, cosine.message);
        CHECK_MESSAGE(cosine.message.find("head on") == std::string::npos, cosine.message);
        CHECK(check(r, "flat").passed);
    }

} // TEST_SUITE

TEST_SUITE("checks: lab 4") { // skipped where the course does not hand lab 4 out

    TEST_CASE("lookAt: v = up and an unnormalized u fail on an oblique up, and only there") {
        if (!labInCourse(sourceDir() / "labs", 4)) return;
        for (const auto& [id, field] : {std::pair{"v_is_up", ": v:"}, std::pair{"u_not_normalized", ": u:"}}) {
            CAPTURE(id);
            const GradeResult r = gradeAgent(courseSetup(), std::string("raylab-bad-") + id);
            const CheckOutcome& basis = check(r, "four_cameras");
            CHECK_FALSE(basis.passed);
            CHECK_MESSAGE(basis.message.find(std::string("not perpendicular to the view") + field) != std::string::npos,
                          basis.message);
            CHECK_MESSAGE(basis.message.find("camera (a)") == std::string::npos,
                          basis.message); // the handout's cameras are right
            CHECK(r.labs[2].points == r.labs[2].maxPoints);
        }
    }

    TEST_CASE("lookAt: a viewport left stale by the constructor is caught, though every figure passes") {
        if (!labInCourse(sourceDir() / "labs", 4)) return;
        const GradeResult r = gradeAgent(courseSetup(), "raylab-bad-stale_viewport");
        const CheckOutcome& viewport = check(r, "viewport_follows");
        CHECK_FALSE(viewport.passed);
        CHECK_MESSAGE(viewport.message.find("top-left corner") != std::string::npos, viewport.message);
        CHECK_MESSAGE(viewport.message.find("call updateViewport()") != std::string::npos, viewport.message);
        CHECK(check(r, "four_cameras").passed);
        for (const char* id : {"lab4_a", "lab4_b", "lab4_c", "lab4_d"})
            CHECK(findFigure(r, id)->passed);
    }

    TEST_CASE("lab 2's checks need no lab 4: with lab 4 a stub, lab 2 keeps every point") {
        if (!labInCourse(sourceDir() / "labs", 4)) return;
        GradeSetup setup = courseSetup();
        // raylab-alone-lab2: lab 2 from solutions/, every other lab the stub; all labs graded (raylab-agent-lab4
        // would answer lab 4 only).
        const GradeResult r = gradeCode(setup, {{binDir() / "raylab-alone-lab2", 0}}, false);
        fs::remove_all(setup.scratch);
        CHECK_MESSAGE(r.labs[1].points == r.labs[1].maxPoints, failures(r));
        CHECK(r.labs[3].points == 0.);
    }

} // TEST_SUITE
