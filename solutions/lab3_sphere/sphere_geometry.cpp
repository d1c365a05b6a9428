// Lab 3: a sphere. The reference solution; students write labs/lab3_sphere/sphere_geometry.cpp.
#include "raylab/sphere_geometry.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace raylab {

// The roots of a t^2 + 2 b' t + c' = 0 in the form of Ray Tracing Gems, chapter 7: the
// discriminant b'^2 - a c' is computed as a (r^2 - |l|^2), l = oc - (b' / a) d (the vector from
// the centre to the ray's closest point), which does not cancel when the sphere is far; and the
// two roots come from q = -b' - sign(b') sqrt(disc), as c' / q and q / a, which never subtract
// two nearly equal numbers.
bool SphereGeometry::intersect(const Ray& ray, float tMin, float tMax, HitRecord& hit) const {
    const glm::vec3& d = ray.direction;
    const glm::vec3 oc = ray.origin - m_center;
    const float a = glm::dot(d, d);
    const float bPrime = glm::dot(oc, d);
    const float c = glm::dot(oc, oc) - m_radius * m_radius;
    const glm::vec3 l = oc - (bPrime / a) * d;
    const float lLength = glm::length(l);
    const float disc = a * (m_radius - lLength) * (m_radius + lLength);
    // Written !(disc >= 0) so that NaN (a ray with a NaN, infinite or zero direction) misses too.
    if (!(disc >= 0.f)) return false;

    const float q = -bPrime - std::copysign(std::sqrt(disc), bPrime);
    float tNear = 0.f, tFar = 0.f; // q = 0 only when b' = disc = 0, so c' = 0: a tangent at t = 0
    if (q != 0.f) {
        tNear = c / q;
        tFar = q / a;
        if (tNear > tFar) std::swap(tNear, tFar);
    }
    float t = tNear;
    if (!(t >= tMin && t <= tMax)) {
        t = tFar;
        if (!(t >= tMin && t <= tMax)) return false;
    }
    hit.t = t;
    hit.position = ray.at(t);
    return true;
}

glm::vec3 SphereGeometry::computeNormal(const glm::vec3& p) const { return (p - m_center) / m_radius; }

} // namespace raylab
