// Lab 4's function checks: the lookAt basis of the handout's four cameras, and the cameras that
// cannot be built.
#include "checks/check_support.h"

#include "raylab/perspective_camera.h"

#include <glm/vec3.hpp>

#include <stdexcept>

using namespace raylab;
using namespace raylab::checks;

namespace {

struct LookAt {
    const char* name;
    glm::vec3 position, target, up;
};

// The cameras of scenes/figures/lab4_{a,b,c,d}.toml.
const LookAt kHandoutCameras[] = {
    {"camera (a)", {0.f, 0.f, -2.f}, {0.f, 0.f, 79.f}, {0.f, 1.f, 0.f}},
    {"camera (b)", {1.f, 0.f, 0.f}, {1.f, 0.f, 1.f}, {0.f, 1.f, 0.f}},
    {"camera (c)", {0.f, 1.f, 0.f}, {0.f, 1.f, 1.f}, {0.f, 1.f, 0.f}},
    {"camera (d)", {4.f, -1.f, 0.f}, {-1.f, -1.f, 2.f}, {0.f, 1.f, 0.f}},
};

// Expects constructing the camera to throw std::invalid_argument.
void expectRefused(const std::string& what, const glm::vec3& position, const glm::vec3& target, const glm::vec3& up) {
    try {
        const PerspectiveCamera camera(200, 100, position, target, up, 60.f);
        fail(what, "std::invalid_argument naming the parameter", "a camera with u = " + show(camera.u()),
             "keep the given checkLookAtParameters(position, target, up) call at the top of the constructor");
    } catch (const std::invalid_argument&) {
    }
}

} // namespace

TEST_SUITE("lab4") {

TEST_CASE("lookAt: the basis of the handout's four cameras") {
    for (const LookAt& c : kHandoutCameras) {
        const PerspectiveCamera camera(600, 400, c.position, c.target, c.up, 60.f);
        const glm::dvec3 w = glm::normalize(glm::dvec3(c.position) - glm::dvec3(c.target));
        const glm::dvec3 u = glm::normalize(glm::cross(glm::dvec3(c.up), w));
        const glm::dvec3 v = glm::cross(w, u);
        const std::string name = c.name;
        expectNear(name + ": w", camera.w(), glm::vec3(w), 1e-5f,
                   "w = normalize(position - target): the camera looks along -w");
        expectNear(name + ": u", camera.u(), glm::vec3(u), 1e-5f,
                   "u = normalize(cross(up, w)) in this order: cross(w, up) mirrors the image");
        expectNear(name + ": v", camera.v(), glm::vec3(v), 1e-5f, "v = cross(w, u), up in the image");
        expectNear(name + ": position", camera.position(), c.position, 1e-6f, "store the position in m_position");
    }
}

TEST_CASE("lookAt: the viewport follows the new frame") {
    const LookAt& c = kHandoutCameras[3];
    const PerspectiveCamera camera(600, 400, c.position, c.target, c.up, 60.f);
    const Ray centre = camera.generateRay(0.5f, 0.5f);
    expectNear("centre ray origin", centre.origin, c.position, 1e-5f, "set m_position before updateViewport()");
    expectNear("centre ray direction", centre.direction, glm::normalize(c.target - c.position), 1e-5f,
               "call updateViewport() after setting the frame, so the screen is in front of the new camera");
}

TEST_CASE("lookAt: the default camera as a lookAt camera") {
    const PerspectiveCamera camera(600, 400, {0.f, 0.f, 0.f}, {0.f, 0.f, 1.f}, {0.f, 1.f, 0.f}, 60.f);
    expectNear("u", camera.u(), glm::vec3(-1.f, 0.f, 0.f), 1e-6f,
               "lookAt((0,0,0), (0,0,1), (0,1,0)) is the default camera, whose u is (-1, 0, 0)");
    expectNear("v", camera.v(), glm::vec3(0.f, 1.f, 0.f), 1e-6f, "v = cross(w, u)");
}

TEST_CASE("lookAt: a degenerate camera is refused with an error") {
    // A constructor that refuses everything earns nothing: a valid camera must be built first.
    const PerspectiveCamera valid(200, 100, {0.f, 0.f, 0.f}, {0.f, 0.f, 1.f}, {0.f, 1.f, 0.f}, 60.f);
    expectNear("a valid camera's w", valid.w(), glm::vec3(0.f, 0.f, -1.f), 1e-6f, "w = normalize(position - target)");
    expectRefused("up parallel to the view direction", {0.f, 0.f, 0.f}, {0.f, 2.f, 0.f}, {0.f, 1.f, 0.f});
    expectRefused("position equal to the target", {1.f, 2.f, 3.f}, {1.f, 2.f, 3.f}, {0.f, 1.f, 0.f});
}

} // TEST_SUITE
