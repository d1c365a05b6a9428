#pragma once
// The renderer: the loop over the pixels of an image, spread over threads by tiles.

#include "raylab/camera.h"
#include "raylab/integrator.h"
#include "raylab/sampler.h"
#include "raylab/texture.h"

#include <cstdint>

namespace raylab {

struct RenderStats {
    double seconds = 0.;
    std::uint64_t primaryRays = 0; // camera rays: pixels x samples per pixel
};

class Renderer {
public:
    Renderer(const Scene& scene, const BaseCamera& camera, const Integrator& integrator);

    // Lab 5: how many samples each pixel averages (at least 1).
    void setNbPixelSamples(int nbSamples);
    int nbPixelSamples() const { return m_nbPixelSamples; }

    void setSampler(SamplerKind kind) { m_sampler = kind; }
    SamplerKind sampler() const { return m_sampler; }
    void setSeed(std::uint64_t seed) { m_seed = seed; }
    // 0 means one thread per core. The image does not depend on the number of threads.
    void setThreads(int threads);
    // A progress bar on standard error, shown only for renders that last over a second.
    void setProgress(bool progress) { m_progress = progress; }

    // Renders the whole image. One centred sample per pixel traces the pixel centre's ray directly;
    // anything else goes through renderPixel. Rethrows the first exception a pixel threw.
    Texture renderImage();
    const RenderStats& stats() const { return m_stats; }

    // Lab 5: the colour of pixel (i, j), the average of nbPixelSamples() samples taken at the
    // offsets that `sampler` serves.
    Color renderPixel(int i, int j, PixelSampler& sampler) const;

private:
    Color renderPixelCentre(int i, int j) const;

    const Scene& m_scene;
    const BaseCamera& m_camera;
    const Integrator& m_integrator;
    int m_nbPixelSamples = 1;
    SamplerKind m_sampler = SamplerKind::Center;
    std::uint64_t m_seed = 0;
    int m_threads = 0;
    bool m_progress = false;
    RenderStats m_stats;
};

} // namespace raylab
