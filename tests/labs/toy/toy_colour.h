#pragma once
// The toy lab's function, declared once: the stub, the solution and the lab's probe include this header.

#include "raylab/ray.h"
#include "raylab/texture.h"

namespace raylab {

// The colour of a ray of direction d: 1 - (d + 1) / 2.
Color toyColour(const Ray& ray);

} // namespace raylab
