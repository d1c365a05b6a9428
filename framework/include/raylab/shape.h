#pragma once
// What a hit refers to: one object of the scene, a sphere or a plane, and what a shading asks of
// any object: its normal at a point and its colour. Each kind (SphereGeometry, Plane) has
//   bool intersect(const Ray&, float tMin, float tMax, HitRecord&) const  (the nearest hit), and
//   bool hits(const Ray&, float tMin, float tMax) const                   (any hit: shadow rays),
// and Scene keeps one list of each. As pbrt-v4's Shape, a kind tag rather than virtual functions:
// the renderer's loop then inlines each kind's code (docs/performance.md).

#include "raylab/texture.h"

#include <glm/vec3.hpp>

namespace raylab {

class Shape {
public:
    // The unit normal at a point p of the object: the sphere's or the plane's own computeNormal.
    // Defined in scene.h, which knows every kind.
    glm::vec3 computeNormal(const glm::vec3& p) const;

    // Its flat colour.
    const Color& color() const { return m_color; }

protected:
    enum class Kind : unsigned char { Sphere, Plane };
    Shape(Kind kind, const Color& color) : m_kind(kind), m_color(color) {}

private:
    Kind m_kind;
    Color m_color;
};

} // namespace raylab
