#pragma once
// Lab 3's answers in double, as its checks (checks.cpp) and its rows of the pixel inspector
// (inspector.cpp) reason about them: where a ray meets a sphere, and the colour each of the lab's
// shadings gives there. Written once for the grader; the reference's own code is solutions/lab3_sphere/.

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <optional>

namespace raylab::grader::lab3 {

// The two roots of |o + t d - c|^2 = r^2, near <= far; nothing when the line passes beside the sphere.
struct Roots {
    double near, far;
};

inline std::optional<Roots> roots(const glm::dvec3& centre, double radius, const glm::dvec3& origin, const glm::dvec3& direction) {
    const glm::dvec3 oc = origin - centre;
    const double a = glm::dot(direction, direction), b = glm::dot(oc, direction);
    const double disc = b * b - a * (glm::dot(oc, oc) - radius * radius);
    if (disc < 0.) return std::nullopt;
    return Roots{(-b - std::sqrt(disc)) / a, (-b + std::sqrt(disc)) / a};
}

// The nearest root t >= 0 (the handout's "which root"); nothing on a miss.
inline std::optional<double> nearestHit(const glm::dvec3& centre, double radius, const glm::dvec3& origin,
                                        const glm::dvec3& direction) {
    const std::optional<Roots> line = roots(centre, radius, origin, direction);
    if (!line) return std::nullopt;
    if (line->near >= 0.) return line->near;
    if (line->far >= 0.) return line->far;
    return std::nullopt;
}

// Lab 3's shadings, numbered as the probe Li takes them (raylab/integrator.h's Shading).
enum Shading { kFlat = 0, kPlaceholder = 1, kCosine = 2 };

// The colour of a hit seen along the unit direction d, where the unit normal is n: flat, the colour;
// cosine, colour * max(-d.n, 0); the placeholder, the same with normalize(1, 1, 1) turned towards the ray.
inline glm::dvec3 shade(int shading, const glm::dvec3& colour, const glm::dvec3& d, const glm::dvec3& n) {
    if (shading == kFlat) return colour;
    glm::dvec3 normal = shading == kCosine ? n : glm::normalize(glm::dvec3(1.));
    if (shading == kPlaceholder && glm::dot(d, normal) > 0.) normal = -normal;
    return colour * std::max(-glm::dot(d, normal), 0.);
}

} // namespace raylab::grader::lab3
