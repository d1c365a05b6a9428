// Every classic mistake is caught by the check the catalogue expects, with the hint the catalogue
// gives it (check_hint) and no other mistake's; a figure it changes is diagnosed as that mistake
// (with its lab, function and formula, and no other lab blamed), no hint names a cause the code does
// not have, and a check that reaches the mistake through another function names the function to fix.
#include "grading_support.h"

#include "src/messages.h"

#include <algorithm>
#include <map>

using namespace raylab::test;

TEST_SUITE("mistakes") {

// What the hints must not say for a mistake, by the prefix of the check's English title: a cause the
// code does not have.
struct WrongCause {
    std::string checks; // the checks concerned: their English titles start with this
    std::string text;   // it must not appear in their messages
};

const std::map<std::string, std::vector<WrongCause>> kWrongCauses{
    // The root choice, not the discriminant: the far-sphere checks must not blame the cancellation.
    {"far_root_first", {{"intersect", "lost to rounding"}, {"intersect", "loses digits"}}},
    // A viewport mistake: generateRay inherits it and must not repeat generateRay's formula.
    {"degrees_as_radians", {{"generateRay", "sy goes down against v"}, {"generateRay", "topLeft includes"}}},
    {"fovy_not_halved", {{"generateRay", "sy goes down against v"}, {"generateRay", "topLeft includes"}}},
    {"aspect_inverted", {{"generateRay", "sy goes down against v"}, {"generateRay", "topLeft includes"}}},
    // A direction as wrong at the origin: the camera's position is not the cause.
    {"plus_sy", {{"generateRay: a camera away", "topLeft includes"}}},
    {"v_flipped", {{"generateRay: a camera away", "topLeft includes"}}},
    {"direction_not_normalized", {{"generateRay: a camera away", "topLeft includes"}, {"generateRay: the centre", "sx goes right"}}},
};

// What the hints must say for a mistake, by the prefix of the check's English title: a check that calls the mistaken
// function only through another names the function to fix; every failing check so named says it.
const std::map<std::string, std::vector<WrongCause>> kRightCauses{
    // Li is right for the far hit that intersect returns: intersect is the function to fix.
    {"far_root_first", {{"Li: cosine", "fix SphereGeometry::intersect first"}}},
    // The corners point the right way, too long: the normalisation, not sx and sy.
    {"direction_not_normalized", {{"generateRay: the centre", "normalize it (glm::normalize)"}}},
};

TEST_CASE("each catalogued mistake is caught and named") {
    const GradeSetup setup = courseSetup();
    // Each patch of the course's labs' grading folders is a catalogued mistake.
    std::size_t patches = 0;
    for (const LabDescription& lab : setup.labs.labs) {
        std::error_code none; // a lab without mistakes
        for (const auto& entry : fs::directory_iterator(sourceDir() / "framework/grader/labs" / lab.id / "mistakes", none))
            patches += entry.path().extension() == ".patch";
    }
    REQUIRE(patches > 0);
    REQUIRE(setup.mistakes.size() == patches);
    for (const Mistake& m : setup.mistakes) {
        CAPTURE(m.id);
        GradeSetup own = courseSetup();
        const GradeResult r = gradeAgent(own, "raylab-mistake-" + m.id);
        CHECK_FALSE(r.allPassed());
        const CheckOutcome* catcher = findCheck(r, m.check);
        REQUIRE_MESSAGE(catcher, "no check \"" << m.check << "\"");
        CHECK_MESSAGE(!catcher->passed, m.id << " is not caught by \"" << m.check << "\"");
        CHECK_MESSAGE(catcher->message.find("Hint:") != std::string::npos, catcher->message);
        // Its own hint, from a check that fails (its catcher, or the check whose cases show that mistake);
        // no check gives the hint of another mistake of the catalogue (a hint that names a mistake needs
        // that mistake's evidence).
        if (!m.checkHint.empty()) {
            const std::string own = raylab::tr(m.checkHint);
            const bool given = std::any_of(r.checks.begin(), r.checks.end(), [&](const CheckOutcome& c) {
                return !c.passed && c.message.find(own) != std::string::npos;
            });
            CHECK_MESSAGE(given, m.id << ": no check gives its hint \"" << own << "\"" << failures(r));
        }
        for (const Mistake& other : setup.mistakes) {
            if (other.checkHint.empty() || other.checkHint == m.checkHint) continue;
            const std::string theirs = raylab::tr(other.checkHint);
            for (const CheckOutcome& c : r.checks)
                CHECK_MESSAGE(c.message.find(theirs) == std::string::npos,
                              m.id << ": \"" << c.name << "\" gives the hint of " << other.id << ": " << c.message);
        }
        MESSAGE(m.id << " caught by \"" << m.check << "\": " << catcher->message);
        // The labs that do not use the mistaken lab keep every point.
        for (const LabOutcome& lab : r.labs) {
            const std::vector<int>& uses = setup.labs.lab(lab.lab)->uses;
            if (lab.lab != m.lab && std::find(uses.begin(), uses.end(), m.lab) == uses.end())
                CHECK_MESSAGE(lab.points == lab.maxPoints, "lab " << lab.lab << failures(r));
        }
        if (const auto wrong = kWrongCauses.find(m.id); wrong != kWrongCauses.end())
            for (const CheckOutcome& c : r.checks)
                for (const WrongCause& cause : wrong->second)
                    if (raylab::tr(raylab::Language::En, "check_title." + c.name).rfind(cause.checks, 0) == 0)
                        CHECK_MESSAGE(c.message.find(cause.text) == std::string::npos,
                                      c.name << " names a cause the code does not have: " << c.message);
        if (const auto right = kRightCauses.find(m.id); right != kRightCauses.end())
            for (const WrongCause& cause : right->second) {
                int said = 0;
                for (const CheckOutcome& c : r.checks)
                    if (raylab::tr(raylab::Language::En, "check_title." + c.name).rfind(cause.checks, 0) == 0 && !c.passed) {
                        ++said;
                        CHECK_MESSAGE(c.message.find(cause.text) != std::string::npos, c.name << " does not say \"" << cause.text
                                                                                              << "\": " << c.message);
                    }
                CHECK_MESSAGE(said >= 1, m.id << ": no failing check starts with " << cause.checks);
            }
        const std::string where = "(lab " + std::to_string(m.lab) + ", " + m.function + ")";
        int named = 0, failing = 0;
        std::string seen;
        for (const FigureOutcome& f : r.figures) {
            if (f.passed) continue;
            ++failing;
            seen += "\n  " + f.id + ": " + (f.diagnosis.empty() ? "(no diagnosis)" : f.diagnosis);
            if (f.diagnosis.find("'" + m.name() + "'") != std::string::npos) {
                ++named;
                CHECK_MESSAGE(f.diagnosis.find(where) != std::string::npos, f.id << " does not say " << where);
                CHECK_MESSAGE(f.diagnosis.find(m.hint()) != std::string::npos, f.id << " does not give the formula");
            } else {
                CHECK_MESSAGE(f.diagnosis.empty(), f.id << " is diagnosed as another mistake: " << f.diagnosis);
            }
            // Only the mistaken lab is blamed, even by a mistake that draws the same picture.
            for (const int lab : setup.labs.numbers())
                if (lab != m.lab)
                    CHECK_MESSAGE(f.diagnosis.find("(lab " + std::to_string(lab) + ",") == std::string::npos,
                                  f.id << " blames lab " << lab << ": " << f.diagnosis);
        }
        // A figure of the course's with a signature of the mistake names it (a left-out lab's figures are not drawn).
        const bool drawn = std::any_of(m.signatures.begin(), m.signatures.end(),
                                       [&](const auto& signature) { return setup.labs.figure(signature.first) != nullptr; });
        if (drawn) CHECK_MESSAGE(named >= 1, m.id << ": no figure names it" << seen);
        MESSAGE(m.id << ": " << failing << " figures fail, " << named << " name it" << seen);
    }
}

} // TEST_SUITE
