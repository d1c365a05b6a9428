// Lab 4's probes, in the agent: the lookAt constructor's frame and viewport, and the cameras it refuses.
#include "grader/protocol/agent/probes.h"
#include "probes.h"

#include "raylab/perspective_camera.h"

#include <stdexcept>

namespace raylab::agent {

namespace {

namespace probes = grader::probes;

probes::BuiltCamera lookAtProbe(probes::LookAtCamera c) {
    const glm::vec3 position(c.position);
    const float fovy = float(c.fovy);
    // Built first elsewhere, then rebuilt: nothing may survive from the first frame.
    PerspectiveCamera camera(c.width, c.height, position + glm::vec3(3.f, -2.f, 1.f), position,
                             glm::vec3(0.f, 1.f, 0.f), fovy);
    camera = PerspectiveCamera(c.width, c.height, position, glm::vec3(c.target), glm::vec3(c.up), fovy);
    return {camera.u(), camera.v(), camera.w(), camera.position(),
            camera.viewportHeight(), camera.viewportWidth(), camera.topLeft()};
}

bool lookAtRefusedProbe(glm::dvec3 position, glm::dvec3 target, glm::dvec3 up) {
    try {
        const PerspectiveCamera camera(200, 100, glm::vec3(position), glm::vec3(target), glm::vec3(up), 60.f);
        return false;
    } catch (const std::invalid_argument&) {
        return true;
    }
}

} // namespace

RAYLAB_REGISTER_PROBE(grader::probes::lookAt, lookAtProbe);
RAYLAB_REGISTER_PROBE(grader::probes::lookAtRefused, lookAtRefusedProbe);

} // namespace raylab::agent
