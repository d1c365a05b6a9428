// Lab 4: a camera you can place. This file is yours to edit.
#include "raylab/perspective_camera.h"

#include <glm/geometric.hpp>

namespace raylab {

PerspectiveCamera::PerspectiveCamera(int width, int height, const glm::vec3& position, const glm::vec3& target,
                                     const glm::vec3& up, float fovyDegrees)
    : PerspectiveCamera(width, height, fovyDegrees) {
    checkLookAtParameters(position, target, up);
    m_position = position;
    m_w = glm::normalize(position - target);
    m_u = glm::normalize(glm::cross(m_w, up)); // mistake: mirrored basis
    m_v = glm::cross(m_w, m_u); // unit already: w and u are orthonormal
    updateViewport();
}

} // namespace raylab
