#pragma once
// How the renderer (raylab/renderer.h) goes over a whole image, and what it measured: the
// framework's part of rendering, for the figures, the benchmarks and the studies. Nothing here is a
// lab's to write.

#include "raylab/detail/sampler_state.h"

#include <cstdint>

namespace raylab {

// Adaptive sampling: nbPixelSamples() samples in every pixel; where the colours of a pixel's
// samples differ by more than `threshold` (in any channel), that pixel, and with `widen` its eight
// neighbours, is rendered again with `maxSamples` samples, which replace the first ones.
struct AdaptiveSettings {
    float threshold = 0.05f;
    int maxSamples = 256;
    bool widen = true; // a thin object one pixel's samples caught may cover its neighbours' too
    SamplerKind within = SamplerKind::Stratified; // how both passes place their samples
};

// Renderer::renderImage's settings; a setting with no meaning is a std::invalid_argument there.
struct RenderSettings {
    SamplerKind sampler = SamplerKind::Center; // Adaptive: two passes, as `adaptive` says
    std::uint64_t seed = 0;
    AdaptiveSettings adaptive;
    int threads = 0;       // 0: one thread per core. The image does not depend on the number of threads.
    bool progress = false; // a progress bar on standard error, shown only for renders that last over a second
};

struct RenderStats {
    double seconds = 0.;
    std::uint64_t primaryRays = 0;   // camera rays: pixels x samples per pixel
    std::uint64_t randomNumbers = 0; // numbers the pixel samplers drew from their generators
    std::uint64_t refinedPixels = 0; // adaptive: the pixels its second pass rendered again
    std::uint64_t shadowRays = 0;    // Scene::occluded's calls: none in a scene without lights
};

} // namespace raylab
