// Lab 3: a sphere. This file is yours to edit.
#include "raylab/sphere_geometry.h"
#include "raylab/todo.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace raylab {

// A point of the ray, o + t d, is on the sphere (centre c, radius r) when |o + t d - c|^2 = r^2:
//   a t^2 + 2 b' t + c' = 0   with   a = d.d,  b' = (o - c).d,  c' = (o - c).(o - c) - r^2.
// No real root: the ray misses. Otherwise keep the nearest root t with tMin <= t <= tMax (the
// smaller root when it is in the interval, else the larger one), and store hit.t and
// hit.position = ray.at(t). The handout explains a form of the roots that stays accurate for
// spheres far away (Ray Tracing Gems, chapter 7).
bool SphereGeometry::intersect(const Ray& ray, float tMin, float tMax, HitRecord& hit) const {
    RAYLAB_TODO("lab 3", "SphereGeometry::intersect");
}

// The outward unit normal at a point p of the sphere: (p - centre) / radius.
glm::vec3 SphereGeometry::computeNormal(const glm::vec3& p) const {
    RAYLAB_TODO("lab 3", "SphereGeometry::computeNormal");
}

} // namespace raylab
