#pragma once
// The renderer: the loop over the pixels of an image, spread over threads by tiles.

#include "raylab/detail/lab_handles.h"
#include "raylab/integrator.h"
#include "raylab/perspective_camera.h"
#include "raylab/sampler.h"
#include "raylab/texture.h"

#include <cstdint>
#include <vector>

namespace raylab {

struct RenderStats {
    double seconds = 0.;
    std::uint64_t primaryRays = 0;   // camera rays: pixels x samples per pixel
    std::uint64_t randomNumbers = 0; // numbers the pixel samplers drew from their generators
    std::uint64_t refinedPixels = 0; // adaptive: the pixels its second pass rendered again
    std::uint64_t shadowRays = 0;    // Scene::occluded's calls: none in a scene without lights
};

// Adaptive sampling: nbPixelSamples() samples in every pixel; where the colours of a pixel's
// samples differ by more than `threshold` (in any channel), that pixel, and with `widen` its eight
// neighbours, is rendered again with `maxSamples` samples, which replace the first ones.
struct AdaptiveSettings {
    float threshold = 0.05f;
    int maxSamples = 256;
    bool widen = true; // a thin object one pixel's samples caught may cover its neighbours' too
    SamplerKind within = SamplerKind::Stratified; // how both passes place their samples
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
    // Used when the sampler is SamplerKind::Adaptive. Throws std::invalid_argument when a setting
    // has no meaning.
    void setAdaptive(const AdaptiveSettings& settings);
    const AdaptiveSettings& adaptive() const { return m_adaptive; }
    // 0 means one thread per core. The image does not depend on the number of threads.
    void setThreads(int threads);
    // A progress bar on standard error, shown only for renders that last over a second.
    void setProgress(bool progress) { m_progress = progress; }

    // Renders the whole image. One centred sample per pixel traces the pixel centre's ray directly;
    // anything else goes through renderPixel (adaptive: twice, see AdaptiveSettings). Rethrows the
    // first exception a pixel threw.
    Texture renderImage();
    const RenderStats& stats() const { return m_stats; }
    // Adaptive: 1 for each pixel (row-major) that the last render's second pass rendered again.
    const std::vector<std::uint8_t>& refinedPixels() const { return m_refined; }

    // Lab 5: the colour of pixel (i, j), the average of nbPixelSamples() samples taken at the
    // offsets that `sampler` serves.
    Color renderPixel(int i, int j, PixelSampler& sampler) const;

private:
    // How renderImage goes over the pixels, on threads (framework/src/render_passes.h): the
    // framework's part, which reads the settings below and fills the statistics.
    friend class RenderPasses;

    // What lab 5's code uses. The camera and the integrator come through handles that call lab 2's
    // and lab 3's classes directly (raylab/detail/lab_handles.h: nothing there is yours to write).
    const Scene& m_scene;
    CameraHandle m_camera;         // the camera: m_camera.generateRay(sx, sy), m_camera.width(), m_camera.height()
    IntegratorHandle m_integrator; // the integrator: m_integrator.Li(m_scene, ray)
    int m_nbPixelSamples = 1;

    // The other settings, and what the last render measured.
    SamplerKind m_sampler = SamplerKind::Center;
    std::uint64_t m_seed = 0;
    AdaptiveSettings m_adaptive;
    int m_threads = 0;
    bool m_progress = false;
    RenderStats m_stats;
    std::vector<std::uint8_t> m_refined;
};

} // namespace raylab
