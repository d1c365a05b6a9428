#pragma once
// Lab 1's function, declared once: the stub, the solution and the lab's grading include this header.

#include "raylab/texture.h"

namespace raylab {

// Lab 1: fills the texture with red = i / (W - 1), green = j / (H - 1), blue = 0
// (0 for a channel whose size is 1).
void fillGradient(Texture& texture);

} // namespace raylab
