// Mistake: the top-left corner is computed without the camera position, and the textbook
// direction then subtracts the position: every ray of a camera away from the origin is off.
#include "raylab/perspective_camera.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>

namespace raylab {

void PerspectiveCamera::updateViewport() {
    m_viewportHeight = 2.f * std::tan(glm::radians(m_fovy) / 2.f) * m_focal;
    m_viewportWidth = m_viewportHeight * aspect();
    m_topLeft = -m_w * m_focal + m_v * (m_viewportHeight / 2.f) - m_u * (m_viewportWidth / 2.f); // mistake: no position
}

Ray PerspectiveCamera::generateRay(float sx, float sy) const {
    const glm::vec3 point = m_topLeft + sx * m_viewportWidth * m_u - sy * m_viewportHeight * m_v;
    return Ray{m_position, glm::normalize(point - m_position)};
}

} // namespace raylab
