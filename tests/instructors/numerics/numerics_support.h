#pragma once
// Helpers of the numerics suite: the lab code (the reference solution) against exact answers, and
// the textbook formula of framework/study/instructors/sphere_formulas.h as the foil that shows why.

#include "sphere_formulas.h"

#include "raylab/random.h"
#include "raylab/scene.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <limits>
#include <vector>

namespace raylab::numerics {

using LD = long double;
constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// The textbook formula in float, the foil: hit or miss for the ray over [0, inf).
inline study::SphereHit<float> textbook(const Ray& ray, const glm::vec3& centre, float radius) {
    using V = study::V3<float>;
    return study::textbookIntersect(V::from(ray.origin), V::from(ray.direction), V::from(centre), radius, 0.f, kInf);
}

// The truth for the float inputs: the stable formula in long double.
inline study::SphereHit<LD> exact(const Ray& ray, const glm::vec3& centre, float radius) {
    using V = study::V3<LD>;
    return study::stableIntersect(V::from(ray.origin), V::from(ray.direction), V::from(centre), LD(radius), LD(0), LD(kInf));
}

// The lab code: SphereGeometry::intersect over [0, inf).
inline bool labHit(const Ray& ray, const glm::vec3& centre, float radius, HitRecord* out = nullptr) {
    HitRecord hit;
    const bool found = SphereGeometry(centre, radius, Color(1.f)).intersect(ray, 0.f, kInf, hit);
    if (out != nullptr) *out = hit;
    return found;
}

// Rays from the origin aimed uniformly over the disc of radius 2r around a sphere `distance` away
// along (0.36, 0.48, 0.8): the rays that come near it, as in `raylab numerics`.
struct NearRays {
    glm::vec3 centre;
    float radius;
    std::vector<Ray> rays;
};

inline NearRays raysNearSphere(double distance, double radius, int count) {
    const glm::dvec3 u(0.36, 0.48, 0.8), e1(0.8, -0.6, 0.), e2(0.48, 0.64, -0.6);
    NearRays set{glm::vec3(distance * u), float(radius), {}};
    Pcg32 rng(11, std::uint64_t(distance));
    for (int k = 0; k < count; ++k) {
        const double rho = 2. * radius * std::sqrt(double(rng.nextFloat()));
        const double phi = 6.283185307179586 * double(rng.nextFloat());
        const glm::dvec3 aim = glm::dvec3(set.centre) + rho * (std::cos(phi) * e1 + std::sin(phi) * e2);
        set.rays.push_back(Ray{glm::vec3(0.f), glm::vec3(glm::normalize(aim))});
    }
    return set;
}

// Fractions of `set`'s rays whose hit/miss differs from the truth: the lab code's and the foil's.
struct Misclassified {
    double lab = 0., textbook = 0.;
};

inline Misclassified misclassified(const NearRays& set) {
    int lab = 0, foil = 0;
    for (const Ray& ray : set.rays) {
        const bool truth = exact(ray, set.centre, set.radius).hit;
        lab += labHit(ray, set.centre, set.radius) != truth;
        foil += textbook(ray, set.centre, set.radius).hit != truth;
    }
    const double n = double(set.rays.size());
    return {lab / n, foil / n};
}

inline bool isFinite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// The angle between two directions, accurate when small.
inline double angle(const glm::dvec3& a, const glm::dvec3& b) {
    return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

} // namespace raylab::numerics
