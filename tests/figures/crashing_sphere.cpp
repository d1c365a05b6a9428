// Lab 3's sphere as a student's that crashes: intersect writes through a null pointer. The crash
// finder must name it (test_figure_crash.cpp); the normal is never asked for.
#include "raylab/sphere_geometry.h"

namespace raylab {

glm::vec3 SphereGeometry::computeNormal(const glm::vec3& point) const { return point; }

bool SphereGeometry::intersect(const Ray&, float, float, HitRecord&) const {
    *static_cast<volatile int*>(nullptr) = 1;
    return false;
}

} // namespace raylab
