#pragma once
// The toy lab's own kind of light, to show that a lab brings one with no framework edit: its lab.toml
// lists the class (`lights`), its grading folder registers it under the scene file's table name
// [[toy_lamp]] (grading/lights.cpp), and its integrator reads it (grading/shadings.cpp).

#include "raylab/light.h"

namespace raylab {

// A lamp that tints what faces it: each surface whose front side sees its position takes its tint.
struct ToyLamp {
    glm::vec3 position{0.f};
    Color tint{1.f};

    ToyLamp shifted(const OriginShift& shift) const { return {shift(position), tint}; }
};

} // namespace raylab
