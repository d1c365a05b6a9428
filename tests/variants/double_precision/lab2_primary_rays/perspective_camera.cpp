// Valid variant: the camera computed in double, the textbook way (through the top-left corner).
#include "raylab/perspective_camera.h"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <cmath>
#include <numbers>

namespace raylab {

void PerspectiveCamera::updateViewport() {
    const double height = 2. * std::tan(double(m_fovy) * std::numbers::pi / 360.) * double(m_focal);
    const double width = height * double(m_width) / double(m_height);
    m_viewportHeight = float(height);
    m_viewportWidth = float(width);
    m_topLeft = glm::vec3(glm::dvec3(m_position) - glm::dvec3(m_w) * double(m_focal) + glm::dvec3(m_v) * (height / 2.) -
                          glm::dvec3(m_u) * (width / 2.));
}

Ray PerspectiveCamera::generateRay(float sx, float sy) const {
    const double height = 2. * std::tan(double(m_fovy) * std::numbers::pi / 360.) * double(m_focal);
    const double width = height * double(m_width) / double(m_height);
    const glm::dvec3 u(m_u), v(m_v), w(m_w);
    const glm::dvec3 topLeft = -w * double(m_focal) + v * (height / 2.) - u * (width / 2.); // relative to the position
    const glm::dvec3 direction = topLeft + double(sx) * width * u - double(sy) * height * v;
    return Ray{m_position, glm::vec3(glm::normalize(direction))};
}

} // namespace raylab
