#pragma once
// A sphere with a flat colour.

#include "raylab/hit_record.h"
#include "raylab/ray.h"
#include "raylab/shape.h"

namespace raylab {

class SphereGeometry final : public Shape {
public:
    SphereGeometry(const glm::vec3& center, float radius, const Color& color);

    // Lab 3: when the ray meets the sphere at some t in [tMin, tMax], stores the nearest such t
    // and its point in `hit` and returns true; otherwise returns false and leaves `hit` alone.
    bool intersect(const Ray& ray, float tMin, float tMax, HitRecord& hit) const;

    // Lab 3: the outward unit normal at a point p of the sphere.
    glm::vec3 computeNormal(const glm::vec3& p) const;

    // Any hit in [tMin, tMax]: intersect's answer, its hit left aside.
    bool hits(const Ray& ray, float tMin, float tMax) const {
        HitRecord scratch;
        return intersect(ray, tMin, tMax, scratch);
    }

    // The same sphere, its centre moved (shape.h).
    SphereGeometry shifted(const OriginShift& shift) const { return SphereGeometry(shift(m_center), m_radius, color()); }
    // How far p is from the sphere's surface.
    float distanceTo(const glm::vec3& p) const;

    const glm::vec3& center() const { return m_center; }
    float radius() const { return m_radius; }

private:
    glm::vec3 m_center;
    float m_radius;
};

} // namespace raylab
