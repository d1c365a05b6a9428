// Mistake: v = up, right only when up is perpendicular to the view direction.
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
    m_v = up; // mistake
    updateViewport();
}

} // namespace raylab
