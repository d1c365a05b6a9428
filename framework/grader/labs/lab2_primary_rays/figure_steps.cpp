// Lab 2's functions as the crash finder calls them (src/figure_steps.h): the default camera, built with
// the figure's render, then each pixel centre's ray.
#include "src/figure_steps.h"

namespace raylab {

namespace {

void defaultCamera(FigureStepContext& c) {
    const SceneDescription& d = c.description;
    if (c.render || d.camera.lookAt || isRegisteredImage(d.shading)) return; // lab 4's camera, or no rays
    c.render.emplace(d, c.options);
}

// Through the pixel's centre, in screen coordinates ((0, 0) and (1, 1) are the image's corners).
void ray(FigureStepContext& c) {
    const PerspectiveCamera& camera = c.render->camera();
    c.ray = camera.generateRay((float(c.i) + 0.5f) / float(camera.width()), (float(c.j) + 0.5f) / float(camera.height()));
}

} // namespace

RAYLAB_REGISTER_FIGURE_STEP("PerspectiveCamera::updateViewport", FigureStage::Setup, defaultCamera);
RAYLAB_REGISTER_FIGURE_STEP("PerspectiveCamera::generateRay", FigureStage::Pixel, ray);

} // namespace raylab
