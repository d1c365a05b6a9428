#pragma once
// Lab 2's probes, typed once for both sides (grader/protocol/probe.h): the parent calls them and reads
// their answers (checks.cpp, inspector.cpp), the agent answers them (probes.cpp).

#include "grader/protocol/probe.h"

namespace raylab::grader::probes {
inline namespace lab2_primary_rays {

// A camera built without lookAt (lab 2 is graded on its own): the default camera's frame
// (u = (-1, 0, 0), v = (0, 1, 0), w = (0, 0, -1)) moved to `position`.
struct DefaultFrameCamera {
    int width = 0, height = 0;
    double fovy = 0.;
    glm::dvec3 position{0.};
    static constexpr auto fields = std::tuple{&DefaultFrameCamera::width, &DefaultFrameCamera::height,
                                              &DefaultFrameCamera::fovy, &DefaultFrameCamera::position};
};
// The virtual screen updateViewport gives a camera: its size, and its top-left corner.
struct Viewport {
    double height = 0., width = 0.;
    glm::dvec3 topLeft{0.};
    static constexpr auto fields = std::tuple{&Viewport::height, &Viewport::width, &Viewport::topLeft};
};
// What generateRay gives.
struct PrimaryRay {
    glm::dvec3 origin{0.}, direction{0.};
    static constexpr auto fields = std::tuple{&PrimaryRay::origin, &PrimaryRay::direction};
};

// The viewport of the default camera (at the origin) of that size and fovy.
inline const protocol::Probe<Viewport(int width, int height, double fovy)> viewport{"viewport"};
inline const protocol::Probe<PrimaryRay(DefaultFrameCamera, double sx, double sy)> generateRay{"generateRay"};

} // namespace lab2_primary_rays
} // namespace raylab::grader::probes
