// Every classic mistake is caught by the check the catalogue expects, and a figure it changes is
// diagnosed as that mistake.
#include "grading_support.h"

#include <algorithm>

using namespace raylab::test;

TEST_SUITE("mistakes") {

TEST_CASE("each catalogued mistake is caught and named") {
    const GradeSetup setup = courseSetup();
    REQUIRE(setup.mistakes.size() >= 13);
    for (const Mistake& m : setup.mistakes) {
        CAPTURE(m.id);
        GradeSetup own = courseSetup();
        const GradeResult r = gradeAgent(own, "raylab-mistake-" + m.id);
        CHECK_FALSE(r.allPassed());
        const CheckOutcome* catcher = findCheck(r, m.check);
        REQUIRE_MESSAGE(catcher, "no check \"" << m.check << "\"");
        CHECK_MESSAGE(!catcher->passed, m.id << " is not caught by \"" << m.check << "\"");
        CHECK_MESSAGE(catcher->message.find("Hint:") != std::string::npos, catcher->message);
        // The labs that do not use the mistaken lab keep every point.
        for (const LabOutcome& lab : r.labs) {
            const std::vector<int>& uses = setup.labs.lab(lab.lab)->uses;
            if (lab.lab != m.lab && std::find(uses.begin(), uses.end(), m.lab) == uses.end())
                CHECK_MESSAGE(lab.points == lab.maxPoints, "lab " << lab.lab << failures(r));
        }
        int named = 0, failing = 0;
        std::string seen;
        for (const FigureOutcome& f : r.figures) {
            if (f.passed) continue;
            ++failing;
            seen += "\n  " + f.id + ": " + (f.diagnosis.empty() ? "(no diagnosis)" : f.diagnosis);
            if (f.diagnosis.find("'" + m.name() + "'") != std::string::npos) ++named;
            else CHECK_MESSAGE(f.diagnosis.empty(), f.id << " is diagnosed as another mistake: " << f.diagnosis);
        }
        if (!m.signatures.empty()) CHECK_MESSAGE(named >= 1, m.id << ": no figure names it" << seen);
        MESSAGE(m.id << ": " << failing << " figures fail, " << named << " name it" << seen);
    }
}

} // TEST_SUITE
