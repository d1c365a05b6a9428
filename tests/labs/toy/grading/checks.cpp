// The toy lab's function checks: toyColour on two fixed directions and on one drawn at grading time,
// one check each (a lab has at least three).
#include "grader/judge/checks/checks.h"
#include "probes.h"

#include "src/messages.h"

#include <string>

namespace raylab::grader {

namespace {

// The check `name`: toyColour(d) is 1 - (d + 1) / 2.
void addColourCheck(LabChecks& checks, const std::string& name, const glm::dvec3& d,
                    SourcePlace where = SourcePlace::here()) {
    checks.add({name, {probes::toyColour(d)}, [d](const auto& out, Judge& judge) {
                    judge.expectNear(tr("what.toy.colour", {{"direction", show(d)}}), probes::toyColour.answer(out[0]),
                                     glm::dvec3(1.) - (d + 1.) / 2., 1e-6, tr("hint.toy.colour"));
                }},
               where);
}

void addChecks(LabChecks& checks, CaseRandom& random) {
    addColourCheck(checks, "straight_ahead", {0., 0., 1.});
    addColourCheck(checks, "to_the_side", {-1., 0., 0.});
    addColourCheck(checks, "drawn_direction", CaseRandom::asFloat(random.unitVector()));
}

} // namespace

RAYLAB_REGISTER_CHECKS(addChecks);

} // namespace raylab::grader
