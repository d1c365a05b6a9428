#pragma once
// The renderer: the loop over the pixels of an image. Lab 5 writes how one pixel's samples are
// taken and averaged (renderPixel); spreading the image over threads, adaptive sampling and the
// statistics are the framework's (raylab/detail/render_settings.h, framework/src/render_passes.cpp).

#include "raylab/detail/lab_handles.h"     // m_camera and m_integrator: the labs' camera and integrator
#include "raylab/detail/render_settings.h" // RenderSettings and RenderStats: the framework's
#include "raylab/sampler.h"
#include "raylab/texture.h"

#include <cstdint>
#include <vector>

namespace raylab {

class Renderer {
public:
    Renderer(const Scene& scene, const BaseCamera& camera, const Integrator& integrator);

    // Lab 5: how many samples each pixel averages (at least 1).
    void setNbPixelSamples(int nbSamples);
    int nbPixelSamples() const { return m_nbPixelSamples; }

    // Lab 5: the colour of pixel (i, j), the average of nbPixelSamples() samples taken at the
    // offsets that `sampler` serves.
    Color renderPixel(int i, int j, PixelSampler& sampler) const;

    // Renders the whole image, each pixel through renderPixel (one centred sample a pixel traces the
    // pixel centre's ray directly), as settings() say; rethrows the first exception a pixel threw.
    Texture renderImage();
    RenderSettings& settings() { return m_settings; }
    const RenderSettings& settings() const { return m_settings; }
    // What the last render measured; adaptive, 1 for each pixel (row-major) its second pass rendered again.
    const RenderStats& stats() const { return m_stats; }
    const std::vector<std::uint8_t>& refinedPixels() const { return m_refined; }

private:
    friend class RenderPasses; // how renderImage goes over the pixels (framework/src/render_passes.h)

    // What lab 5's code uses.
    const Scene& m_scene;
    CameraHandle m_camera;         // the camera: m_camera.generateRay(sx, sy), m_camera.width(), m_camera.height()
    IntegratorHandle m_integrator; // the integrator: m_integrator.Li(m_scene, ray)
    int m_nbPixelSamples = 1;

    // The framework's.
    RenderSettings m_settings;
    RenderStats m_stats;
    std::vector<std::uint8_t> m_refined;
};

} // namespace raylab
