#pragma once
// A point light: it shines equally in every direction from one point (docs/conventions.md, "Lights").

#include "raylab/texture.h"

#include <glm/vec3.hpp>

namespace raylab {

struct PointLight {
    glm::vec3 position{0.f};
    // Its radiant intensity, per channel: a surface at distance r facing it receives intensity / r^2.
    Color intensity{1.f};
};

} // namespace raylab
