// Lab 4: a camera you can place. This file is yours to edit.
#include "raylab/perspective_camera.h"
#include "raylab/todo.h"

#include <glm/geometric.hpp>

namespace raylab {

// The camera at `position` looking at `target`. Build its frame (right-handed, the camera looks along -w):
//   w = normalize(position - target)
//   u = normalize(cross(up, w))
//   v = cross(w, u)
// store them in m_w, m_u, m_v, set m_position, then call updateViewport() (lab 2) for the new frame.
PerspectiveCamera::PerspectiveCamera(int width, int height, const glm::vec3& position, const glm::vec3& target,
                                     const glm::vec3& up, float fovyDegrees)
    : PerspectiveCamera(width, height, fovyDegrees) { // given: checks the size and fovy
    checkLookAtParameters(position, target, up);      // given: refuses a frame that cannot be built
    RAYLAB_TODO("lab 4", "the lookAt constructor PerspectiveCamera(width, height, position, target, up, fovy)");
}

} // namespace raylab
