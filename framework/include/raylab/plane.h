#pragma once
// An infinite plane with a flat colour: the points x with dot(normal, x - point) = 0.

#include "raylab/hit_record.h"
#include "raylab/ray.h"
#include "raylab/shape.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace raylab {

class Plane final : public Shape {
public:
    // `normal` need not be unit (it is normalized); throws std::invalid_argument when it is zero or
    // not finite, or when the point is not finite.
    Plane(const glm::vec3& point, const glm::vec3& normal, const Color& color);

    // The one t where the ray crosses the plane, when it is in [tMin, tMax]. A ray parallel to the
    // plane, lying in it included, misses (a plane has no thickness), and so does a NaN ray.
    // Inline, as Scene::intersect (docs/performance.md).
    bool intersect(const Ray& ray, float tMin, float tMax, HitRecord& hit) const {
        if (const float t = crossing(ray); within(t, tMin, tMax)) {
            hit.t = t;
            hit.position = ray.at(t);
            return true;
        }
        return false;
    }
    bool hits(const Ray& ray, float tMin, float tMax) const { return within(crossing(ray), tMin, tMax); }

    // The unit normal as constructed, on both sides (docs/conventions.md).
    glm::vec3 computeNormal(const glm::vec3&) const { return m_normal; }

    // The same plane through the moved point (shape.h).
    Plane shifted(const OriginShift& shift) const { return Plane(shift(m_point), m_normal, color()); }
    // How far p is from the plane.
    float distanceTo(const glm::vec3& p) const { return std::abs(glm::dot(p - m_point, m_normal)); }

    const glm::vec3& point() const { return m_point; }
    const glm::vec3& normal() const { return m_normal; }

private:
    // dot(n, o + t d - p) = 0 gives t = dot(n, p - o) / dot(n, d). A ray parallel to the plane has
    // dot(n, d) = 0 and gets an infinite t, or NaN (0 / 0) when it lies in the plane.
    float crossing(const Ray& ray) const {
        return glm::dot(m_normal, m_point - ray.origin) / glm::dot(m_normal, ray.direction);
    }
    // NaN fails every comparison, so it is not within either.
    static bool within(float t, float tMin, float tMax) { return t >= tMin && t <= tMax && std::isfinite(t); }

    glm::vec3 m_point;
    glm::vec3 m_normal;
};

} // namespace raylab
