// Lab 4's probes, in the agent: the lookAt constructor's frame and viewport, and the cameras it refuses.
#include "grader/protocol/agent/probes.h"
#include "probes.h"

#include "raylab/perspective_camera.h"

#include <stdexcept>

namespace raylab::agent {

namespace {

std::vector<double> lookAtProbe(ProbeInputs in) {
    const int width = in.integer(), height = in.integer();
    const glm::vec3 position = in.vec3(), target = in.vec3(), up = in.vec3();
    const float fovy = in.real();
    // Built first elsewhere, then rebuilt: nothing may survive from the first frame.
    PerspectiveCamera camera(width, height, position + glm::vec3(3.f, -2.f, 1.f), position, glm::vec3(0.f, 1.f, 0.f),
                             fovy);
    camera = PerspectiveCamera(width, height, position, target, up, fovy);
    std::vector<double> out;
    for (const glm::vec3& v : {camera.u(), camera.v(), camera.w(), camera.position()})
        appendOutputs(out, v);
    out.insert(out.end(), {camera.viewportHeight(), camera.viewportWidth()});
    appendOutputs(out, camera.topLeft());
    return out;
}

std::vector<double> lookAtRefusedProbe(ProbeInputs in) {
    const glm::vec3 position = in.vec3(), target = in.vec3(), up = in.vec3();
    try {
        const PerspectiveCamera camera(200, 100, position, target, up, 60.f);
        return {0.};
    } catch (const std::invalid_argument&) {
        return {1.};
    }
}

} // namespace

RAYLAB_REGISTER_PROBE(grader::probes::lookAt, lookAtProbe);
RAYLAB_REGISTER_PROBE(grader::probes::lookAtRefused, lookAtRefusedProbe);

} // namespace raylab::agent
