#pragma once
// Lab 4's answers in double, as its checks (checks.cpp) and its rows of the pixel inspector
// (inspector.cpp) reason about them: the lookAt frame, and the viewport and primary rays that follow
// from it. The last are lab 2's formulas, written again here: a grading folder includes no other
// lab's, so that a course may give lab 2 or leave it out. The reference's own code is
// solutions/lab4_lookat_camera/.

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <cmath>
#include <numbers>

namespace raylab::grader::lab4 {

// A camera's frame: u to the right of the picture, v up, and w backwards (the camera looks along -w).
struct Frame {
    glm::dvec3 position, u, v, w;
};

// lookAt: w = normalize(position - target), u = normalize(cross(up, w)), v = cross(w, u).
inline Frame lookAt(const glm::dvec3& position, const glm::dvec3& target, const glm::dvec3& up) {
    const glm::dvec3 w = glm::normalize(position - target), u = glm::normalize(glm::cross(up, w));
    return {position, u, glm::cross(w, u), w};
}

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

} // namespace raylab::grader::lab4
