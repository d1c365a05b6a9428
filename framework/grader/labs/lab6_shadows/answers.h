#pragma once
// Lab 6's answers in double, as its checks (checks.cpp) and its rows of the pixel inspector
// (inspector.cpp) reason about them: where a ray (a primary ray, or a shadow ray towards a light)
// meets each kind of object of the lab's scenes. Written once for the grader; the reference's own
// code is solutions/lab6_shadows/.

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <cmath>
#include <optional>

namespace raylab::grader::lab6 {

// The first t > tMin where the ray's line meets the sphere; nothing when none does.
inline std::optional<double> sphereCrossing(const glm::dvec3& centre, double radius, const glm::dvec3& origin,
                                            const glm::dvec3& direction, double tMin) {
    const glm::dvec3 oc = origin - centre;
    const double a = glm::dot(direction, direction), b = glm::dot(oc, direction);
    const double disc = b * b - a * (glm::dot(oc, oc) - radius * radius);
    if (disc < 0.) return std::nullopt;
    for (const double t : {(-b - std::sqrt(disc)) / a, (-b + std::sqrt(disc)) / a})
        if (t > tMin) return t;
    return std::nullopt;
}

// The t where the ray's line meets the plane through `point` with this normal, if t > tMin; nothing
// for a ray parallel to it.
inline std::optional<double> planeCrossing(const glm::dvec3& point, const glm::dvec3& normal, const glm::dvec3& origin,
                                           const glm::dvec3& direction, double tMin) {
    const double along = glm::dot(normal, direction);
    if (along == 0.) return std::nullopt;
    const double t = glm::dot(normal, point - origin) / along;
    if (t > tMin) return t;
    return std::nullopt;
}

} // namespace raylab::grader::lab6
