// No check passes on nothing: for each lab, an agent whose lab N does nothing (made from the stubs by
// tests/grading/CMakeLists.txt: each RAYLAB_TODO dropped from a function that returns nothing, and
// replaced by `return {};` elsewhere; the other labs are the reference) earns no point of lab N,
// neither from a check nor from a figure.
#include "grading_support.h"

#include <doctest/doctest.h>

#include <string>

using namespace raylab::test;

TEST_SUITE("nothing") {

TEST_CASE("a lab whose functions do nothing (default values, setters that ignore their argument) earns no point") {
    for (const int lab : courseSetup().labs.numbers()) {
        CAPTURE(lab);
        const GradeResult result = gradeAgent(courseSetup(), "raylab-nothing-lab" + std::to_string(lab));
        int items = 0;
        for (const CheckOutcome& check : result.checks)
            if (check.lab == lab) {
                ++items;
                CHECK_MESSAGE(check.points == 0., "lab " << lab << ", check '" << check.name << "' gives " << check.points
                                                         << " of " << check.maxPoints << " points to nothing");
            }
        for (const FigureOutcome& figure : result.figures)
            if (figure.lab == lab) {
                ++items;
                CHECK_MESSAGE(figure.points == 0., "lab " << lab << ", figure " << figure.id << " gives " << figure.points
                                                          << " points to nothing");
            }
        CHECK(items > 0);
    }
}

} // TEST_SUITE
