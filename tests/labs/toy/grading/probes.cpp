// The toy lab's probe, in the agent: toyColour of a ray along the direction the parent drew.
#include "grader/protocol/agent/probes.h"
#include "probes.h"

#include "raylab/ray.h"
#include "raylab/texture.h"

namespace raylab {

Color toyColour(const Ray& ray); // the toy lab's function (labs/lab6_toy/toy_colour.cpp)

namespace agent {

namespace {

std::vector<double> toyColourProbe(ProbeInputs in) {
    std::vector<double> out;
    appendOutputs(out, toyColour(Ray{glm::vec3(0.f), in.vec3()}));
    return out;
}

} // namespace

RAYLAB_REGISTER_PROBE(grader::probes::toyColour, toyColourProbe);

} // namespace agent

} // namespace raylab
