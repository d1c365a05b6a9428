#pragma once
// The toy lab's own kind of object, to show that a lab brings one with no framework edit: its
// lab.toml lists the class (`shapes`), its grading folder registers it under the scene file's
// table name [[toy_square]] (grading/shapes.cpp). Written whole here: the toy's student writes
// toyColour only.

#include "raylab/hit_record.h"
#include "raylab/ray.h"
#include "raylab/shape.h"

#include <cmath>

namespace raylab {

// A square facing the default camera: the points (x, y, center.z) with |x - center.x| and
// |y - center.y| at most half its side.
class ToySquare final : public Shape {
public:
    ToySquare(const glm::vec3& center, float side, const Color& color) : Shape(color), m_center(center), m_half(side / 2.f) {}

    bool intersect(const Ray& r, float tMin, float tMax, HitRecord& hit) const {
        const float t = (m_center.z - r.origin.z) / r.direction.z; // infinite or NaN when parallel
        if (!(t >= tMin && t <= tMax && std::isfinite(t))) return false;
        const glm::vec3 p = r.at(t);
        if (!(std::abs(p.x - m_center.x) <= m_half && std::abs(p.y - m_center.y) <= m_half)) return false;
        hit.t = t;
        hit.position = p;
        return true;
    }
    bool hits(const Ray& ray, float tMin, float tMax) const {
        HitRecord scratch;
        return intersect(ray, tMin, tMax, scratch);
    }
    glm::vec3 computeNormal(const glm::vec3&) const { return {0.f, 0.f, -1.f}; }
    ToySquare shifted(const OriginShift& shift) const { return ToySquare(shift(m_center), 2.f * m_half, color()); }

private:
    glm::vec3 m_center;
    float m_half;
};

} // namespace raylab
