// Lab 7: triangles. The reference solution; students write labs/lab7_triangles/triangle.cpp.
#include "shapes.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace raylab {

// Möller and Trumbore (1997): o + t d = a + u e1 + v e2 solved by Cramer's rule, each determinant a
// triple product. det = e1 . (d x e2) is 0 exactly when d is parallel to the plane: then no hit, and
// no division (a 0 / 0 would be NaN, a x / 0 infinite). A NaN ray fails every comparison below.
bool Triangle::intersect(const Ray& ray, float tMin, float tMax, HitRecord& hit) const {
    const glm::vec3 e1 = m_b - m_a, e2 = m_c - m_a;
    const glm::vec3 p = glm::cross(ray.direction, e2);
    const float det = glm::dot(e1, p);
    if (det == 0.f) return false;
    const float inverse = 1.f / det;
    const glm::vec3 s = ray.origin - m_a;
    const float u = glm::dot(s, p) * inverse;
    if (!(u >= 0.f && u <= 1.f)) return false;
    const glm::vec3 q = glm::cross(s, e1);
    const float v = glm::dot(ray.direction, q) * inverse;
    if (!(v >= 0.f && u + v <= 1.f)) return false;
    const float t = glm::dot(e2, q) * inverse;
    if (!(t >= tMin && t <= tMax && std::isfinite(t))) return false;
    hit.t = t;
    hit.position = ray.at(t);
    return true;
}

glm::vec3 Triangle::computeNormal(const glm::vec3&) const { return glm::normalize(glm::cross(m_b - m_a, m_c - m_a)); }

} // namespace raylab
