#include "raylab/renderer.h"

#include "src/render_passes.h"

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

namespace raylab {

Renderer::Renderer(const Scene& scene, const BaseCamera& camera, const Integrator& integrator)
    : m_scene(scene), m_camera(camera), m_integrator(integrator) {}

void Renderer::setThreads(int threads) {
    if (threads < 0) throw std::invalid_argument("Renderer: threads = " + std::to_string(threads) + " is negative");
    m_threads = threads;
}

void Renderer::setAdaptive(const AdaptiveSettings& s) {
    if (!(s.threshold >= 0.f) || !std::isfinite(s.threshold))
        throw std::invalid_argument("adaptive: threshold = " + std::to_string(s.threshold) + "; it must be finite and >= 0");
    if (s.maxSamples < 1)
        throw std::invalid_argument("adaptive: max_samples = " + std::to_string(s.maxSamples) + "; at least 1");
    if (s.within == SamplerKind::Adaptive)
        throw std::invalid_argument("adaptive: its passes need a sampler other than adaptive");
    m_adaptive = s;
}

Texture Renderer::renderImage() {
    const auto start = std::chrono::steady_clock::now();
    m_stats = RenderStats{};
    m_refined.clear();
    Texture image = RenderPasses::render(*this);
    m_stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return image;
}

} // namespace raylab
