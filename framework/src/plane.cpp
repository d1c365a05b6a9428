#include "raylab/plane.h"

#include "src/text.h"

#include <stdexcept>

namespace raylab {

Plane::Plane(const glm::vec3& point, const glm::vec3& normal, const Color& color)
    : Shape(color), m_point(point), m_normal(normal) {
    if (!std::isfinite(point.x) || !std::isfinite(point.y) || !std::isfinite(point.z))
        throw std::invalid_argument("plane: point = " + showVector(point) + " is not finite");
    // The length in double: a normal of tiny or huge finite floats still has a direction.
    const double length = glm::length(glm::dvec3(normal));
    if (!(length > 0.) || !std::isfinite(length))
        throw std::invalid_argument("plane: normal = " + showVector(normal) + " has no direction");
    m_normal = glm::vec3(glm::dvec3(normal) / length);
}

} // namespace raylab
