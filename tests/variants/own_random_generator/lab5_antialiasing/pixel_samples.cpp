// Valid variant: the samples drawn from the student's own generator (std::mt19937 seeded per
// pixel) instead of the PixelSampler: another random sequence, the same distribution.
#include "raylab/renderer.h"

#include <random>
#include <stdexcept>
#include <string>

namespace raylab {

void Renderer::setNbPixelSamples(int nbSamples) {
    if (nbSamples < 1) throw std::invalid_argument("setNbPixelSamples: " + std::to_string(nbSamples));
    m_nbPixelSamples = nbSamples;
}

Color Renderer::renderPixel(int i, int j, PixelSampler& /*sampler*/) const {
    std::mt19937 generator(std::uint32_t(j * 100003 + i));
    std::uniform_real_distribution<float> uniform(0.f, 1.f);
    const float width = float(m_camera.width()), height = float(m_camera.height());
    Color sum(0.f);
    for (int k = 0; k < m_nbPixelSamples; ++k) {
        const float x = uniform(generator), y = uniform(generator);
        sum += m_integrator.Li(m_scene, m_camera.generateRay((float(i) + x) / width, (float(j) + y) / height));
    }
    return sum / float(m_nbPixelSamples);
}

} // namespace raylab
