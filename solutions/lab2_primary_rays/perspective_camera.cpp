// Lab 2: primary rays. The reference solution; students write labs/lab2_primary_rays/perspective_camera.cpp.
#include "raylab/perspective_camera.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>

namespace raylab {

void PerspectiveCamera::updateViewport() {
    m_viewportHeight = 2.f * std::tan(glm::radians(m_fovy) / 2.f) * m_focal;
    m_viewportWidth = m_viewportHeight * aspect();
    m_topLeft = m_position - m_w * m_focal + m_v * (m_viewportHeight / 2.f) - m_u * (m_viewportWidth / 2.f);
}

Ray PerspectiveCamera::generateRay(float sx, float sy) const {
    // point - position, written relative to the camera: the same vector as
    // m_topLeft + sx * W * u - sy * H * v - m_position, without subtracting two large world
    // positions (which loses every digit when the camera is far from the origin).
    const glm::vec3 toScreen = -m_w * m_focal + m_u * (m_viewportWidth * (sx - 0.5f)) +
                               m_v * (m_viewportHeight * (0.5f - sy));
    return Ray{m_position, glm::normalize(toScreen)};
}

} // namespace raylab
