// Mistake: the frame changes but the viewport is never rebuilt (the default camera's stays).
#include "raylab/perspective_camera.h"

#include <glm/geometric.hpp>

namespace raylab {

PerspectiveCamera::PerspectiveCamera(int width, int height, const glm::vec3& position, const glm::vec3& target,
                                     const glm::vec3& up, float fovyDegrees)
    : PerspectiveCamera(width, height, fovyDegrees) {
    checkLookAtParameters(position, target, up);
    m_position = position;
    m_w = glm::normalize(position - target);
    m_u = glm::normalize(glm::cross(up, m_w));
    m_v = glm::cross(m_w, m_u); // unit already: w and u are orthonormal
}

} // namespace raylab
