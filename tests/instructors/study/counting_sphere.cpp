// SphereGeometry's two lab-3 functions, counting their calls. This test program takes lab 3's
// shading (RayCastIntegrator::Li) from solutions/, unchanged, and its sphere from here.
#include "counting_sphere.h"

#include "raylab/sphere_geometry.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace raylab {

namespace test {
std::atomic<std::uint64_t> sphereIntersections{0};
std::atomic<std::uint64_t> sphereNormals{0};
} // namespace test

bool SphereGeometry::intersect(const Ray& ray, float tMin, float tMax, HitRecord& hit) const {
    test::sphereIntersections.fetch_add(1, std::memory_order_relaxed);
    const glm::vec3 oc = ray.origin - m_center;
    const float a = glm::dot(ray.direction, ray.direction);
    const float b = glm::dot(oc, ray.direction);
    const float disc = b * b - a * (glm::dot(oc, oc) - m_radius * m_radius);
    if (disc < 0.f) return false;
    for (float t : {(-b - std::sqrt(disc)) / a, (-b + std::sqrt(disc)) / a})
        if (t >= tMin && t <= tMax) {
            hit.t = t;
            hit.position = ray.at(t);
            return true;
        }
    return false;
}

glm::vec3 SphereGeometry::computeNormal(const glm::vec3& p) const {
    test::sphereNormals.fetch_add(1, std::memory_order_relaxed);
    return (p - m_center) / m_radius;
}

} // namespace raylab
