// The sphere's constructor: it refuses the spheres lab 3's intersection cannot handle. Its
// intersect and computeNormal are lab 3's: the student's file in labs/ (or its solution).
#include "raylab/sphere_geometry.h"

#include "src/text.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <stdexcept>

namespace raylab {

SphereGeometry::SphereGeometry(const glm::vec3& center, float radius, const Color& color)
    : Shape(color), m_center(center), m_radius(radius) {
    if (!(radius > 0.f) || !std::isfinite(radius))
        throw std::invalid_argument("sphere: radius = " + showNumber(radius) +
                                    " has no meaning; it must be positive and finite");
    // The intersection needs r^2 (and |o - c|^2 of the same size): past 1.8e19 it overflows float.
    if (!std::isfinite(radius * radius))
        throw std::invalid_argument("sphere: radius = " + showNumber(radius) + " is too large: its square overflows float");
    if (!std::isfinite(center.x) || !std::isfinite(center.y) || !std::isfinite(center.z))
        throw std::invalid_argument("sphere: center = " + showVector(center) + " is not finite");
}

float SphereGeometry::distanceTo(const glm::vec3& p) const { return std::abs(glm::length(p - m_center) - m_radius); }

} // namespace raylab
