// Lab 2: primary rays. This file is yours to edit.
#include "raylab/perspective_camera.h"
#include "raylab/todo.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>

namespace raylab {

// The virtual screen stands at distance m_focal in front of the camera (along -m_w).
// Compute
//   m_viewportHeight = 2 tan(fovy / 2) * m_focal   (m_fovy is in degrees: glm::radians converts)
//   m_viewportWidth  = m_viewportHeight * aspect()
//   m_topLeft        = m_position - m_w * m_focal + m_v * m_viewportHeight / 2 - m_u * m_viewportWidth / 2
void PerspectiveCamera::updateViewport() {
    RAYLAB_TODO("lab 2", "PerspectiveCamera::updateViewport");
}

// The ray from the camera position through the screen point (sx, sy): (0, 0) is the top-left corner
// of the screen, (1, 1) the bottom-right one. Going right follows m_u; going down goes against m_v.
//   point     = m_topLeft + sx * m_viewportWidth * m_u - sy * m_viewportHeight * m_v
//   direction = normalize(point - m_position)
Ray PerspectiveCamera::generateRay(float sx, float sy) const {
    RAYLAB_TODO("lab 2", "PerspectiveCamera::generateRay");
}

} // namespace raylab
