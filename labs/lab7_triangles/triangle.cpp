// Lab 7: triangles. This file is yours to edit.
#include "shapes.h"
#include "raylab/todo.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace raylab {

// A point of the ray, o + t d, is in the triangle (a, b, c) when it is a + u (b - a) + v (c - a)
// with u >= 0, v >= 0 and u + v <= 1. Solve o + t d = a + u e1 + v e2 (e1 = b - a, e2 = c - a) for
// t, u, v with Cramer's rule, as Möller and Trumbore do (the handout gives the steps):
//   p = d x e2,  det = e1 . p;  no hit when det is 0 (the ray is parallel to the triangle's plane);
//   s = o - a,  u = (s . p) / det;  q = s x e1,  v = (d . q) / det,  t = (e2 . q) / det.
// A hit only when u and v are in the triangle and tMin <= t <= tMax: then store hit.t and
// hit.position = ray.at(t), and return true. Otherwise return false and leave hit alone.
bool Triangle::intersect(const Ray& ray, float tMin, float tMax, HitRecord& hit) const {
    RAYLAB_TODO("lab 7", "Triangle::intersect");
}

// The unit normal, the same everywhere on the triangle: cross(b - a, c - a), normalized.
glm::vec3 Triangle::computeNormal(const glm::vec3& p) const {
    RAYLAB_TODO("lab 7", "Triangle::computeNormal");
}

} // namespace raylab
