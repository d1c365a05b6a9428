// Lab 1's rows of the pixel inspector (grader/inspector/inspector_steps.h), for its gradient figure:
// the pixel's column and row, then the colour fillGradient writes there, asked of the student's
// function on the figure's size. The reference's colour is the grader's reference picture, so it is
// compared in its 8 bits: no formula of the lab is written here.
#include "grader/inspector/inspector_steps.h"
#include "probes.h"

namespace raylab::grader::inspector {

namespace {

void gradient(PixelContext& pixel, Inspection& inspection) {
    const SceneDescription& d = pixel.scene;
    if (d.shading != "gradient" || pixel.coloured) return; // its name in this lab's shadings.cpp
    const int call = inspection.call(probes::fillGradient, {double(d.width), double(d.height)});
    const std::size_t first = 3 * (std::size_t(pixel.y) * std::size_t(d.width) + std::size_t(pixel.x));
    inspection.add({.key = "lab1_pixel", .lab = 1, .reference = Json::array({pixel.x, pixel.y, d.width, d.height})});
    inspection.add({.key = "lab1_colour", .function = "fillGradient", .lab = 1, .reference = pixel.picturePixel("reference"),
                    .student = values(call, first, 3), .inBytes = true});
    pixel.coloured = true;
}

} // namespace

RAYLAB_REGISTER_INSPECTOR_STEP(InspectorStage::Path, gradient);

} // namespace raylab::grader::inspector
