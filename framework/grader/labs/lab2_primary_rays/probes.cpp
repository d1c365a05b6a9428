// Lab 2's probes, in the agent: the default camera's viewport, and generateRay of a camera moved
// away from the origin (no lookAt: lab 2 is graded on its own).
#include "grader/protocol/agent/probes.h"
#include "probes.h"

#include "raylab/perspective_camera.h"

namespace raylab::agent {

namespace {

namespace probes = grader::probes;

probes::Viewport viewportProbe(int width, int height, double fovy) {
    const PerspectiveCamera camera(width, height, float(fovy));
    return {camera.viewportHeight(), camera.viewportWidth(), camera.topLeft()};
}

probes::PrimaryRay generateRayProbe(probes::DefaultFrameCamera c, double sx, double sy) {
    const PerspectiveCamera camera(c.width, c.height, glm::vec3(c.position), float(c.fovy));
    const Ray ray = camera.generateRay(float(sx), float(sy));
    return {ray.origin, ray.direction};
}

} // namespace

RAYLAB_REGISTER_PROBE(grader::probes::viewport, viewportProbe);
RAYLAB_REGISTER_PROBE(grader::probes::generateRay, generateRayProbe);

} // namespace raylab::agent
