// Valid variant: the textbook quadratic (b = 2 oc.d, disc = b^2 - 4ac), in double, which keeps
// enough digits for the spheres of the labs and the 10^4-radii check.
#include "raylab/sphere_geometry.h"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <cmath>

namespace raylab {

bool SphereGeometry::intersect(const Ray& ray, float tMin, float tMax, HitRecord& hit) const {
    const glm::dvec3 d(ray.direction), oc = glm::dvec3(ray.origin) - glm::dvec3(m_center);
    const double a = glm::dot(d, d), b = 2. * glm::dot(oc, d);
    const double c = glm::dot(oc, oc) - double(m_radius) * double(m_radius);
    const double disc = b * b - 4. * a * c;
    if (disc < 0.) return false;
    const double root = std::sqrt(disc);
    for (double t : {(-b - root) / (2. * a), (-b + root) / (2. * a)})
        if (t >= double(tMin) && t <= double(tMax)) {
            hit.t = float(t);
            hit.position = glm::vec3(glm::dvec3(ray.origin) + t * d);
            return true;
        }
    return false;
}

glm::vec3 SphereGeometry::computeNormal(const glm::vec3& p) const {
    return glm::vec3((glm::dvec3(p) - glm::dvec3(m_center)) / double(m_radius));
}

} // namespace raylab
