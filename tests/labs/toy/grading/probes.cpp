// The toy lab's probe, in the agent: toyColour of a ray along the direction the parent drew.
#include "grader/protocol/agent/probes.h"
#include "probes.h"

#include "toy_colour.h"

namespace raylab::agent {

namespace {

std::vector<double> toyColourProbe(ProbeInputs in) {
    std::vector<double> out;
    appendOutputs(out, toyColour(Ray{glm::vec3(0.f), in.vec3()}));
    return out;
}

} // namespace

RAYLAB_REGISTER_PROBE(grader::probes::toyColour, toyColourProbe);

} // namespace raylab::agent
