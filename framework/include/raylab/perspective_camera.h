#pragma once
// A pinhole camera. Its virtual screen stands at distance focal() in front of the position, is
// 2 tan(fovy / 2) * focal high and aspect times as wide.

#include "raylab/camera.h"

namespace raylab {

class PerspectiveCamera final : public BaseCamera {
public:
    // The default camera: at the origin, looking along +z, up +y (so u = (-1, 0, 0)).
    // Throws std::invalid_argument when a size or fovy has no meaning.
    PerspectiveCamera(int width, int height, float fovyDegrees = 60.f);

    // The default camera's frame moved to `position` (no lookAt needed: lab 2's code alone).
    PerspectiveCamera(int width, int height, const glm::vec3& position, float fovyDegrees);

    // Lab 4: a camera at `position` looking at `target`, `up` giving the vertical.
    PerspectiveCamera(int width, int height, const glm::vec3& position, const glm::vec3& target,
                      const glm::vec3& up, float fovyDegrees = 60.f);

    // Lab 2: computes the viewport size and its top-left corner from the frame and fovy.
    void updateViewport();

    // Lab 2.
    Ray generateRay(float sx, float sy) const override;

    float fovy() const { return m_fovy; }
    float focal() const { return m_focal; }
    float viewportWidth() const { return m_viewportWidth; }
    float viewportHeight() const { return m_viewportHeight; }
    const glm::vec3& topLeft() const { return m_topLeft; }

private:
    float m_fovy;          // vertical field of view, full angle, in degrees
    float m_focal = 1.f;   // distance from the position to the virtual screen
    float m_viewportWidth = 0.f;
    float m_viewportHeight = 0.f;
    glm::vec3 m_topLeft{0.f}; // world position of the screen's top-left corner
};

// Throws std::invalid_argument naming the parameter when a lookAt frame cannot be built:
// a NaN or infinite coordinate, position == target, or up parallel to the view direction.
void checkLookAtParameters(const glm::vec3& position, const glm::vec3& target, const glm::vec3& up);

} // namespace raylab
