// Lab 5: antialiasing. This file is yours to edit.
#include "raylab/renderer.h"
#include "raylab/todo.h"

namespace raylab {

// Store the number of samples per pixel in m_nbPixelSamples. Fewer than 1 sample has no meaning:
// throw std::invalid_argument then.
void Renderer::setNbPixelSamples(int nbSamples) {
    RAYLAB_TODO("lab 5", "Renderer::setNbPixelSamples");
}

// The colour of pixel (i, j): the average of m_nbPixelSamples samples. For each sample, ask the
// sampler for an offset inside the pixel (sampler.next2D(), in [0, 1)^2), aim at the screen point
//   sx = (i + offset.x) / W,  sy = (j + offset.y) / H     (W = m_camera.width(), H = m_camera.height())
// and add m_integrator.Li(m_scene, m_camera.generateRay(sx, sy)). Return the sum / m_nbPixelSamples.
// Tip: sum in double (glm::dvec3): a float sum drifts once a pixel has millions of samples
// (docs/numerics.md, "accumulation").
Color Renderer::renderPixel(int i, int j, PixelSampler& sampler) const {
    RAYLAB_TODO("lab 5", "Renderer::renderPixel");
}

} // namespace raylab
