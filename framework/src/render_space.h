#pragma once
// Large world coordinates (docs/numerics.md, section 9). Floats 10^7 from the origin are 1 apart,
// so hit points there, and the normals taken from them, are off by up to 1. The renderer therefore
// works in a render space whose origin is a point of a 1024-unit grid near the camera (a "floating
// origin"): the camera stays within 512 of it, and what the camera sees keeps about 6e-5 of
// precision wherever it is. A camera within 512 of the world origin renders in world coordinates,
// exactly as before, so every lab sees the positions its figures were made with.

#include "raylab/scene.h"

namespace raylab {

inline constexpr float kRenderCell = 1024.f;

class RenderSpace {
public:
    // The render space of a camera at `cameraPosition`: its origin is each coordinate rounded to a
    // multiple of kRenderCell (exact in float).
    explicit RenderSpace(const glm::vec3& cameraPosition);

    const glm::vec3& origin() const { return m_origin; }
    // `point` - origin(), taken in double (exact for two floats) and rounded once to float.
    glm::vec3 toRender(const glm::vec3& point) const;
    // The scene with every position (each object's, each light's) moved by -origin().
    Scene toRender(const Scene& scene) const;

private:
    glm::vec3 m_origin;
};

} // namespace raylab
