#pragma once
// A sphere with a flat colour.

#include "raylab/hit_record.h"
#include "raylab/ray.h"
#include "raylab/texture.h"

namespace raylab {

class SphereGeometry {
public:
    SphereGeometry(const glm::vec3& center, float radius, const Color& color);

    // Lab 3: when the ray meets the sphere at some t in [tMin, tMax], stores the nearest such t
    // and its point in `hit` and returns true; otherwise returns false and leaves `hit` alone.
    bool intersect(const Ray& ray, float tMin, float tMax, HitRecord& hit) const;

    // Lab 3: the outward unit normal at a point p of the sphere.
    glm::vec3 computeNormal(const glm::vec3& p) const;

    const glm::vec3& center() const { return m_center; }
    float radius() const { return m_radius; }
    const Color& color() const { return m_color; }

private:
    glm::vec3 m_center;
    float m_radius;
    Color m_color;
};

} // namespace raylab
