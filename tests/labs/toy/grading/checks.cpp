// The toy lab's function check: toyColour on fixed directions and on one drawn at grading time.
#include "grader/judge/checks/checks.h"
#include "probes.h"

#include "src/messages.h"

namespace raylab::grader {

namespace {

void addChecks(LabChecks& checks, CaseRandom& random) {
    const std::vector<glm::dvec3> directions{{0., 0., 1.}, {-1., 0., 0.}, CaseRandom::asFloat(random.unitVector())};
    std::vector<protocol::Call> calls;
    for (const glm::dvec3& d : directions) {
        std::vector<double> inputs;
        appendInputs(inputs, d);
        calls.push_back({probes::toyColour, inputs});
    }
    checks.add({"toyColour: 1 - (d + 1) / 2 for each direction d", calls, [directions](const auto& out, Judge& judge) {
                    for (std::size_t k = 0; k < directions.size(); ++k)
                        judge.expectNear(tr("what.toy.colour", {{"direction", show(directions[k])}}),
                                         Outputs(out[k]).vec3(), glm::dvec3(1.) - (directions[k] + 1.) / 2., 1e-6,
                                         tr("hint.toy.colour"));
                }});
}

} // namespace

RAYLAB_REGISTER_CHECKS(addChecks);

} // namespace raylab::grader
