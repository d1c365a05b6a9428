// Lab 4's function as the crash finder calls it (src/figure_steps.h): the lookAt camera, built with the
// figure's render.
#include "src/figure_steps.h"

namespace raylab {

namespace {

void lookAtCamera(FigureStepContext& c) {
    const SceneDescription& d = c.description;
    if (c.render || !d.camera.lookAt || isRegisteredImage(d.shading)) return; // lab 2's camera, or no rays
    c.render.emplace(d, c.options);
}

} // namespace

RAYLAB_REGISTER_FIGURE_STEP("the lookAt constructor PerspectiveCamera(width, height, position, target, up, fovy)",
                            FigureStage::Setup, lookAtCamera);

} // namespace raylab
