#pragma once
// What a hit refers to: one object of the scene, of any kind (a sphere, a plane, a lab's triangle),
// and what a shading asks of any object: its normal at a point and its colour.
//
// A kind of object is a final class deriving from Shape, with
//   bool intersect(const Ray&, float tMin, float tMax, HitRecord&) const  the nearest hit: its t and position
//   bool hits(const Ray&, float tMin, float tMax) const                   any hit (shadow rays)
//   glm::vec3 computeNormal(const glm::vec3& p) const                     the unit normal at p
//   Kind shifted(const OriginShift& shift) const                          itself, each position p as shift(p)
// and, optionally, float distanceTo(const glm::vec3& p) const (how far p is from its surface: the
// grader's rounding probe, src/shadow_rays.h). Scene keeps one array per kind and tests each array
// with its kind's own code (raylab/scene.h); a scene file names the kind by the name it is registered
// under (raylab/kind_registry.h).

#include "raylab/origin_shift.h"
#include "raylab/texture.h"

#include <glm/vec3.hpp>

namespace raylab {

class Shape {
public:
    // The unit normal at a point p of the object: its kind's computeNormal. Defined in scene.h. An
    // object a hit refers to is in a scene, which knows its kind; any other has no normal here (NaN).
    glm::vec3 computeNormal(const glm::vec3& p) const;

    // Its flat colour.
    const Color& color() const { return m_color; }

protected:
    explicit Shape(const Color& color) : m_color(color) {}

private:
    friend struct Scene; // which sets m_kind when it takes the object
    static constexpr unsigned char kNoKind = 0xff;
    unsigned char m_kind = kNoKind; // its kind's place in SceneShapeKinds (scene.h)
    Color m_color;
};

} // namespace raylab
