// Lab 1's picture, by the name its scene file's [render] shading gives: the gradient, drawn without rays.
#include "gradient.h"
#include "raylab/integrator_registry.h"

namespace raylab {

namespace {

Texture gradient(int width, int height) {
    Texture texture(width, height);
    fillGradient(texture);
    return texture;
}

const ImageRegistrar kGradient("gradient", gradient);

} // namespace

} // namespace raylab
