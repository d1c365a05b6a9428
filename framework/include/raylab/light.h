#pragma once
// A point light: it shines equally in every direction from one point (docs/conventions.md, "Lights").
//
// A lab may bring another kind of light (an area light, say): a class that is not a Shape, with
//   Kind shifted(const OriginShift& shift) const   itself, each position p as shift(p)
// and whatever its lab's integrator asks of it. Scene keeps one array per kind (scene.h); a scene
// file names the kind by the name it is registered under (raylab/kind_registry.h).

#include "raylab/origin_shift.h"
#include "raylab/texture.h"

#include <glm/vec3.hpp>

namespace raylab {

struct PointLight {
    glm::vec3 position{0.f};
    // Its radiant intensity, per channel: a surface at distance r facing it receives intensity / r^2.
    Color intensity{1.f};

    PointLight shifted(const OriginShift& shift) const { return {shift(position), intensity}; }
};

} // namespace raylab
