#include "raylab/renderer.h"

#include "src/render_passes.h"

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

namespace raylab {

Renderer::Renderer(const Scene& scene, const BaseCamera& camera, const Integrator& integrator)
    : m_scene(scene), m_camera(camera), m_integrator(integrator) {}

namespace {

// A setting with no meaning is refused before any pixel is rendered.
void checkSettings(const RenderSettings& s) {
    if (s.threads < 0) throw std::invalid_argument("Renderer: threads = " + std::to_string(s.threads) + " is negative");
    const AdaptiveSettings& a = s.adaptive;
    if (!(a.threshold >= 0.f) || !std::isfinite(a.threshold))
        throw std::invalid_argument("adaptive: threshold = " + std::to_string(a.threshold) + "; it must be finite and >= 0");
    if (a.maxSamples < 1)
        throw std::invalid_argument("adaptive: max_samples = " + std::to_string(a.maxSamples) + "; at least 1");
    if (a.within == SamplerKind::Adaptive)
        throw std::invalid_argument("adaptive: its passes need a sampler other than adaptive");
}

} // namespace

Texture Renderer::renderImage() {
    checkSettings(m_settings);
    const auto start = std::chrono::steady_clock::now();
    m_stats = RenderStats{};
    m_refined.clear();
    Texture image = RenderPasses::render(*this);
    m_stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return image;
}

} // namespace raylab
