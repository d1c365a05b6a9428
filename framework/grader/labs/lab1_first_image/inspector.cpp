// Lab 1's rows of the pixel inspector (grader/inspector/inspector_steps.h), for its gradient figure:
// the pixel's column and row, then the colour fillGradient writes there, asked of the student's
// function on the figure's size. The reference's colour is the grader's reference picture, so it is
// compared in its 8 bits: no formula of the lab is written here.
#include "grader/inspector/inspector_steps.h"
#include "probes.h"

#include <vector>

namespace raylab::grader::inspector {

namespace {

// The colour the student's fillGradient wrote at pixel (x, y) of a W x H texture (call `call`); null
// when it gave no texture or one of another size, whose pixels are not where the figure's are.
StudentValue writtenColour(int call, int width, int height, int x, int y) {
    return answerOf(probes::fillGradient, call, [=](const std::vector<glm::dvec3>& pixels) -> Json {
        if (pixels.size() != std::size_t(width) * std::size_t(height)) return {};
        return shown(pixels[std::size_t(y) * std::size_t(width) + std::size_t(x)]);
    });
}

void gradient(PixelContext& pixel, Inspection& inspection) {
    const SceneDescription& d = pixel.scene;
    if (d.shading != "gradient" || pixel.coloured) return; // its name in this lab's shadings.cpp
    const int call = inspection.call(probes::fillGradient(d.width, d.height));
    inspection.add({.key = "lab1_pixel", .lab = 1, .reference = Json::array({pixel.x, pixel.y, d.width, d.height})});
    inspection.add({.key = "lab1_colour", .function = "fillGradient", .lab = 1, .reference = pixel.picturePixel("reference"),
                    .student = writtenColour(call, d.width, d.height, pixel.x, pixel.y), .inBytes = true});
    pixel.coloured = true;
}

} // namespace

RAYLAB_REGISTER_INSPECTOR_STEP(InspectorStage::Path, gradient);

} // namespace raylab::grader::inspector
