// The toy lab's probe, in the agent: toyColour of a ray along the direction the parent drew.
#include "grader/protocol/agent/probes.h"
#include "probes.h"

#include "toy_colour.h"

namespace raylab::agent {

namespace {

glm::dvec3 toyColourProbe(glm::dvec3 direction) { return toyColour(Ray{glm::vec3(0.f), glm::vec3(direction)}); }

} // namespace

RAYLAB_REGISTER_PROBE(grader::probes::toyColour, toyColourProbe);

} // namespace raylab::agent
