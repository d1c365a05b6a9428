// No check passes on nothing: for each lab, an agent whose lab N does nothing (made from the stubs by
// tests/grading/CMakeLists.txt: each RAYLAB_TODO dropped from a function that returns nothing, and
// replaced by `return {};` elsewhere; the other labs are the reference) earns no point of lab N,
// neither from a check nor from a figure.
#include "grading_support.h"

#include <doctest/doctest.h>

#include <set>
#include <string>
#include <utility>

using namespace raylab::test;

namespace {

// The checks that still give points to a lab that does nothing (issue 21, item 10): each needs a
// case a default value does not answer. Listed so that the rest is held to zero now; the test fails
// when one of them stops passing on nothing, so that its line goes.
const std::set<std::pair<int, std::string>> kStillPassOnNothing{
    {2, "generateRay: the centre and the four corners of the default camera"}, // Ray{} is the centre's ray?
    {2, "generateRay: directions are unit vectors"},                           // Ray{}'s direction is a unit vector
    {3, "intersect: a ray beside the sphere misses"},                          // `false` misses
    {3, "intersect: a sphere behind the ray is not hit"},                      // `false` does not hit
    {4, "lookAt: the default camera as a lookAt camera"},                      // the given constructor made it
    {4, "lookAt: a degenerate camera is refused with an error"},               // the given check refuses it
};

} // namespace

TEST_SUITE("nothing") {

TEST_CASE("a lab whose functions do nothing (default values, setters that ignore their argument) earns no point") {
    for (const int lab : courseSetup().labs.numbers()) {
        CAPTURE(lab);
        const GradeResult result = gradeAgent(courseSetup(), "raylab-nothing-lab" + std::to_string(lab));
        int items = 0;
        for (const CheckOutcome& check : result.checks)
            if (check.lab == lab && kStillPassOnNothing.count({lab, check.name})) {
                CHECK_MESSAGE(check.points > 0., "lab " << lab << ", check '" << check.name
                                                        << "' gives nothing to nothing now: remove it from kStillPassOnNothing");
            } else if (check.lab == lab) {
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
