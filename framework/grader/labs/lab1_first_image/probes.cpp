// Lab 1's probes, in the agent: fillGradient on a texture whose every pixel starts at -1.
#include "grader/protocol/agent/probes.h"
#include "probes.h"

#include "gradient.h"

namespace raylab::agent {

namespace {

std::vector<glm::dvec3> fillGradientProbe(int width, int height) {
    Texture t(width, height);
    for (int j = 0; j < height; ++j) // a pixel never written stays visible
        for (int i = 0; i < width; ++i)
            t.setPixel(i, j, Color(-1.f));
    fillGradient(t);
    std::vector<glm::dvec3> pixels;
    for (int j = 0; j < height; ++j)
        for (int i = 0; i < width; ++i)
            pixels.emplace_back(t.getPixel(i, j));
    return pixels;
}

} // namespace

RAYLAB_REGISTER_PROBE(grader::probes::fillGradient, fillGradientProbe);

} // namespace raylab::agent
