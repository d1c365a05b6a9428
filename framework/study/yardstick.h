#pragma once
// The yardstick of `raylab bench` (docs/performance.md): lab 5's picture drawn by one plain function,
// the formulas of solutions/ written out in a single loop, with no class, no virtual call and no
// framework in between. raylab renders the same image; its time over the yardstick's is what the
// framework costs per ray.

#include "src/scene_file.h"

#include <vector>

namespace raylab::study {

// The linear pixels (row-major) of a scene like the bench figure's (roles = ["bench"]): the default
// camera, one sphere, cosine shading, the random sampler, any size, samples and seed. Bit for bit
// the image the reference labs render. Throws std::invalid_argument for any other kind of scene.
std::vector<Color> renderYardstick(const SceneDescription& scene);

} // namespace raylab::study
