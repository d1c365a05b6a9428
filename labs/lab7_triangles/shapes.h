#pragma once
// Lab 7's kind of object, the triangle: the scene file's [[triangle]] tables (its corners a, b, c and
// its colour), kept by Scene beside the spheres and planes. You write its intersect and its
// computeNormal in triangle.cpp; the rest is given.

#include "raylab/hit_record.h"
#include "raylab/ray.h"
#include "raylab/shape.h"

#include <cmath>
#include <stdexcept>

namespace raylab {

class Triangle final : public Shape {
public:
    // Throws std::invalid_argument when a corner is not finite.
    Triangle(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const Color& color)
        : Shape(color), m_a(a), m_b(b), m_c(c) {
        for (const glm::vec3& p : {a, b, c})
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
                throw std::invalid_argument("triangle: a corner is not finite");
    }

    // The point where the ray crosses the triangle, when its t is in [tMin, tMax]: hit.t and
    // hit.position. A ray parallel to the triangle's plane misses. Yours: triangle.cpp.
    bool intersect(const Ray& ray, float tMin, float tMax, HitRecord& hit) const;
    // Whether the ray crosses it with t in [tMin, tMax] (the shadow test).
    bool hits(const Ray& ray, float tMin, float tMax) const {
        HitRecord scratch;
        return intersect(ray, tMin, tMax, scratch);
    }
    // The unit normal, the same at every point p: on the side from which a, b, c turn
    // counter-clockwise (the right-hand rule). Yours: triangle.cpp.
    glm::vec3 computeNormal(const glm::vec3& p) const;

    // The same triangle, each corner moved (raylab/shape.h).
    Triangle shifted(const OriginShift& shift) const { return Triangle(shift(m_a), shift(m_b), shift(m_c), color()); }

    const glm::vec3& a() const { return m_a; }
    const glm::vec3& b() const { return m_b; }
    const glm::vec3& c() const { return m_c; }

private:
    glm::vec3 m_a, m_b, m_c;
};

} // namespace raylab
