// Lab 2's probes, in the agent: the default camera's viewport, and generateRay of a camera moved
// away from the origin (no lookAt: lab 2 is graded on its own).
#include "grader/protocol/agent/probes.h"
#include "probes.h"

#include "raylab/perspective_camera.h"

namespace raylab::agent {

namespace {

std::vector<double> viewportProbe(ProbeInputs in) {
    const int width = in.integer(), height = in.integer();
    const PerspectiveCamera camera(width, height, in.real());
    std::vector<double> out{camera.viewportHeight(), camera.viewportWidth()};
    appendOutputs(out, camera.topLeft());
    return out;
}

std::vector<double> generateRayProbe(ProbeInputs in) {
    const int width = in.integer(), height = in.integer();
    const float fovy = in.real();
    const PerspectiveCamera camera(width, height, in.vec3(), fovy);
    const float sx = in.real();
    const Ray ray = camera.generateRay(sx, in.real());
    std::vector<double> out;
    appendOutputs(out, ray.origin);
    appendOutputs(out, ray.direction);
    return out;
}

} // namespace

RAYLAB_REGISTER_PROBE(grader::probes::viewport, viewportProbe);
RAYLAB_REGISTER_PROBE(grader::probes::generateRay, generateRayProbe);

} // namespace raylab::agent
