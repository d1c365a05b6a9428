#pragma once
// Where a ray's line crosses a triangle's plane, in double, as the grader reasons about it (checks.cpp,
// inspector.cpp): Möller and Trumbore's t, u, v.

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

} // namespace raylab::grader::lab7
