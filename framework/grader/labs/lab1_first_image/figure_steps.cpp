// Lab 1's function as the crash finder calls it (src/figure_steps.h): the gradient, the whole image at once.
#include "gradient.h"
#include "src/figure_steps.h"

namespace raylab {

namespace {

void gradient(FigureStepContext& c) {
    if (c.description.shading != "gradient") return; // its name in this lab's shadings.cpp
    Texture texture(c.description.width, c.description.height);
    fillGradient(texture);
}

} // namespace

RAYLAB_REGISTER_FIGURE_STEP("fillGradient", FigureStage::Setup, gradient);

} // namespace raylab
