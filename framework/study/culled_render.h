#pragma once
// A reference render of many small spheres at the cost of about one sphere test a ray: the image
// is cut into tiles, and a tile's rays are asked only about the spheres they can meet.
//
// Only for the reference solutions' renders (the studies' references): a student's intersect that
// draws a sphere larger than it is would be hidden where its true bounds are culled.

#include "src/scene_file.h"
#include "raylab/texture.h"

namespace raylab::study {

// The image renderScene(d) draws, bit for bit (each pixel's samples depend on the pixel alone, and
// the spheres left out are the ones none of its rays can meet), faster when the spheres are many
// and small. For a render through lab 5's renderPixel: adaptive sampling (whose second pass looks at
// the neighbours) and one centred sample are std::invalid_argument.
Texture renderCulled(const SceneDescription& d, int threads);

} // namespace raylab::study
