#pragma once
// The interface every camera offers the renderer: a ray for a point of the screen.

#include "raylab/ray.h"

#include <glm/vec3.hpp>

namespace raylab {

class BaseCamera {
public:
    BaseCamera(int width, int height);
    virtual ~BaseCamera() = default;

    // The primary ray through the screen point (sx, sy): (0, 0) is the top-left corner of the image,
    // (1, 1) the bottom-right one. The pixel (i, j) has its centre at ((i + 0.5) / W, (j + 0.5) / H).
    virtual Ray generateRay(float sx, float sy) const = 0;

    int width() const { return m_width; }
    int height() const { return m_height; }
    float aspect() const { return float(m_width) / float(m_height); }

    // The camera frame (right-handed): u points to the right of the image, v up, and w backwards,
    // so the camera looks along -w. See docs/conventions.md.
    const glm::vec3& position() const { return m_position; }
    const glm::vec3& u() const { return m_u; }
    const glm::vec3& v() const { return m_v; }
    const glm::vec3& w() const { return m_w; }

protected:
    int m_width;
    int m_height;
    // The default frame is lookAt(position (0,0,0), target (0,0,1), up (0,1,0)).
    glm::vec3 m_position{0.f, 0.f, 0.f};
    glm::vec3 m_u{-1.f, 0.f, 0.f};
    glm::vec3 m_v{0.f, 1.f, 0.f};
    glm::vec3 m_w{0.f, 0.f, -1.f};
};

} // namespace raylab
