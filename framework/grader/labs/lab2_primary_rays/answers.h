#pragma once
// Lab 2's answers in double, as its checks (checks.cpp) and its rows of the pixel inspector
// (inspector.cpp) reason about them: the default camera's viewport, the screen's top-left corner and the primary
// rays' directions. Written once for the grader; the reference's own code is solutions/lab2_primary_rays/.

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <cmath>
#include <numbers>

namespace raylab::grader::lab2 {

// A camera's frame: u to the right of the picture, v up, and w backwards (the camera looks along -w).
struct Frame {
    glm::dvec3 position, u, v, w;
};

// The default frame (docs/conventions.md): u = (-1, 0, 0), v = (0, 1, 0), w = (0, 0, -1).
inline Frame defaultFrame(const glm::dvec3& position) { return {position, {-1., 0., 0.}, {0., 1., 0.}, {0., 0., -1.}}; }

// The virtual screen at distance 1: 2 tan(fovy / 2) high, as wide as the picture's aspect makes it.
struct Viewport {
    double height, width;
};

inline Viewport viewport(double fovyDegrees, int width, int height) {
    const double screenHeight = 2. * std::tan(fovyDegrees / 2. * std::numbers::pi / 180.);
    return {screenHeight, screenHeight * width / height};
}

inline glm::dvec3 topLeft(const Frame& f, const Viewport& s) { return f.position - f.w + f.v * (s.height / 2.) - f.u * (s.width / 2.); }

// The unit direction of the primary ray through the screen point (sx, sy) (docs/conventions.md).
inline glm::dvec3 direction(const Frame& f, const Viewport& s, double sx, double sy) {
    return glm::normalize(topLeft(f, s) + sx * s.width * f.u - sy * s.height * f.v - f.position);
}

} // namespace raylab::grader::lab2
