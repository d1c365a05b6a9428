#pragma once
// Lab 4's probes, typed once for both sides (grader/protocol/probe.h): the parent calls them and reads
// their answers (checks.cpp, inspector.cpp), the agent answers them (probes.cpp).

#include "grader/protocol/probe.h"

namespace raylab::grader::probes {
inline namespace lab4_lookat_camera {

// What the lookAt constructor is given: PerspectiveCamera(width, height, position, target, up, fovy).
struct LookAtCamera {
    int width = 0, height = 0;
    glm::dvec3 position{0.}, target{0.}, up{0.};
    double fovy = 0.;
    static constexpr auto fields = std::tuple{&LookAtCamera::width,  &LookAtCamera::height, &LookAtCamera::position,
                                              &LookAtCamera::target, &LookAtCamera::up,     &LookAtCamera::fovy};
};
// What it builds: the frame, and the viewport updateViewport places in it.
struct BuiltCamera {
    glm::dvec3 u{0.}, v{0.}, w{0.}, position{0.};
    double viewportHeight = 0., viewportWidth = 0.;
    glm::dvec3 topLeft{0.};
    static constexpr auto fields =
        std::tuple{&BuiltCamera::u, &BuiltCamera::v, &BuiltCamera::w, &BuiltCamera::position,
                   &BuiltCamera::viewportHeight, &BuiltCamera::viewportWidth, &BuiltCamera::topLeft};
};

inline const protocol::Probe<BuiltCamera(LookAtCamera)> lookAt{"lookAt"};
// Whether the lookAt constructor refuses that camera (throws std::invalid_argument) rather than build it.
inline const protocol::Probe<bool(glm::dvec3 position, glm::dvec3 target, glm::dvec3 up)> lookAtRefused{
    "lookAtRefused"};

} // namespace lab4_lookat_camera
} // namespace raylab::grader::probes
