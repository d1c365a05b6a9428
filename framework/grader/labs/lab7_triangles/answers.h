#pragma once
// Lab 7's answers in double, as its checks (checks.cpp) and its rows of the pixel inspector
// (inspector.cpp) reason about them: where a ray's line crosses a triangle's plane (Möller and
// Trumbore's t, u, v) and the triangle's normal. Written once for the grader; the reference's own
// code is solutions/lab7_triangles/.

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <optional>

namespace raylab::grader::lab7 {

struct Crossing {
    double t, u, v;
    bool inside() const { return u >= 0. && v >= 0. && u + v <= 1.; }
};

// Nothing for a line parallel to the plane.
inline std::optional<Crossing> crossing(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& origin,
                                        const glm::dvec3& direction) {
    const glm::dvec3 e1 = b - a, e2 = c - a, s = origin - a;
    const glm::dvec3 p = glm::cross(direction, e2), q = glm::cross(s, e1);
    const double det = glm::dot(e1, p);
    if (det == 0.) return std::nullopt;
    return Crossing{glm::dot(e2, q) / det, glm::dot(s, p) / det, glm::dot(direction, q) / det};
}

// The unit normal by the right-hand rule from a to b to c.
inline glm::dvec3 normal(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) { return glm::normalize(glm::cross(b - a, c - a)); }

} // namespace raylab::grader::lab7
