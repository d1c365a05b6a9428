// Mistake: the textbook quadratic in float (b = 2 oc.d, disc = b^2 - 4ac). Right for the labs'
// sphere at distance 3; at 10^4 radii b^2 - 4ac is lost to rounding (docs/numerics.md).
#include "raylab/sphere_geometry.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace raylab {

bool SphereGeometry::intersect(const Ray& ray, float tMin, float tMax, HitRecord& hit) const {
    const glm::vec3 oc = ray.origin - m_center;
    const float a = glm::dot(ray.direction, ray.direction);
    const float b = 2.f * glm::dot(oc, ray.direction);
    const float c = glm::dot(oc, oc) - m_radius * m_radius;
    const float disc = b * b - 4.f * a * c;
    if (disc < 0.f) return false;
    const float root = std::sqrt(disc);
    for (float t : {(-b - root) / (2.f * a), (-b + root) / (2.f * a)})
        if (t >= tMin && t <= tMax) {
            hit.t = t;
            hit.position = ray.at(t);
            return true;
        }
    return false;
}

glm::vec3 SphereGeometry::computeNormal(const glm::vec3& p) const { return (p - m_center) / m_radius; }

} // namespace raylab
