// Lab 5's function as the crash finder calls it (src/figure_steps.h): a pixel's samples, when the
// figure takes more than one.
#include "src/figure_steps.h"

namespace raylab {

namespace {

void samples(FigureStepContext& c) {
    const SceneDescription& d = c.description;
    if (d.samples <= 1) return;
    PixelSampler sampler(d.sampler, d.samples, d.seed, c.i, c.j, d.width);
    (void)c.render->renderer().renderPixel(c.i, c.j, sampler);
}

} // namespace

RAYLAB_REGISTER_FIGURE_STEP("Renderer::renderPixel", FigureStage::Pixel, samples);

} // namespace raylab
