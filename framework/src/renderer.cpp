#include "raylab/renderer.h"

#include "raylab/terminal.h"

#include <glm/common.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <functional>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>

namespace raylab {

namespace {

constexpr int kTileSize = 16;

struct Tile {
    int x0, y0, x1, y1;
};

std::vector<Tile> makeTiles(int width, int height) {
    std::vector<Tile> tiles;
    for (int y = 0; y < height; y += kTileSize)
        for (int x = 0; x < width; x += kTileSize)
            tiles.push_back({x, y, std::min(x + kTileSize, width), std::min(y + kTileSize, height)});
    return tiles;
}

// Runs work(tile, randomNumbers) for every tile over `threads` threads; each worker counts the
// random numbers it drew in its own variable, added up at the end. Rethrows the first exception.
std::uint64_t forEachTile(const std::vector<Tile>& tiles, int threadsWanted, bool progress,
                          const std::function<void(const Tile&, std::uint64_t&)>& work) {
    std::atomic<std::size_t> nextTile{0};
    std::atomic<std::size_t> tilesDone{0};
    std::atomic<bool> failed{false};
    std::atomic<std::uint64_t> drawn{0};
    std::exception_ptr firstError;
    std::mutex errorMutex;

    auto worker = [&] {
        std::uint64_t myDrawn = 0;
        try {
            for (std::size_t t = nextTile++; t < tiles.size() && !failed; t = nextTile++) {
                work(tiles[t], myDrawn);
                ++tilesDone;
            }
        } catch (...) {
            std::lock_guard lock(errorMutex);
            if (!failed.exchange(true)) firstError = std::current_exception();
        }
        drawn += myDrawn;
    };

    unsigned threads = threadsWanted > 0 ? unsigned(threadsWanted) : std::max(1u, std::thread::hardware_concurrency());
    threads = unsigned(std::max<std::size_t>(1, std::min<std::size_t>(threads, tiles.size())));
    std::vector<std::thread> workers;
    for (unsigned k = 1; k < threads; ++k) workers.emplace_back(worker);
    if (progress) {
        ProgressBar bar(tiles.size());
        // The calling thread watches; the workers render.
        workers.emplace_back(worker);
        while (tilesDone < tiles.size() && !failed) {
            bar.update(tilesDone);
            std::this_thread::sleep_for(std::chrono::milliseconds(100));
        }
        for (auto& w : workers) w.join();
        bar.finish();
    } else {
        worker();
        for (auto& w : workers) w.join();
    }
    if (firstError) std::rethrow_exception(firstError);
    return drawn;
}

// The integrator seen by adaptive sampling's first pass: passes every colour through and keeps the
// range of the colours since the last reset. One per worker thread, so nothing is shared.
class SpreadProbe final : public Integrator {
public:
    explicit SpreadProbe(const Integrator& inner) : m_inner(inner) {}
    Color Li(const Scene& scene, const Ray& ray) const override {
        const Color c = m_inner.Li(scene, ray);
        m_lo = glm::min(m_lo, c);
        m_hi = glm::max(m_hi, c);
        return c;
    }
    void reset() {
        m_lo = Color(INFINITY);
        m_hi = Color(-INFINITY);
    }
    // The largest difference between two samples in one channel; NaN when a sample was NaN.
    float spread() const {
        const Color d = m_hi - m_lo;
        return std::max({d.r, d.g, d.b});
    }

private:
    const Integrator& m_inner;
    mutable Color m_lo{INFINITY};
    mutable Color m_hi{-INFINITY};
};

// The seed of adaptive sampling's second pass: new samples, not the first pass's again.
std::uint64_t secondPassSeed(std::uint64_t seed) { return seed ^ 0x9e3779b97f4a7c15ull; }

} // namespace

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

Color Renderer::renderPixelCentre(int i, int j) const {
    const float sx = (float(i) + 0.5f) / float(m_camera.width());
    const float sy = (float(j) + 0.5f) / float(m_camera.height());
    return m_integrator.Li(m_scene, m_camera.generateRay(sx, sy));
}

std::vector<std::uint8_t> Renderer::pixelsToRefine(const std::vector<float>& spread) const {
    const int width = m_camera.width(), height = m_camera.height();
    std::vector<std::uint8_t> refine(spread.size(), 0);
    const int reach = m_adaptive.widen ? 1 : 0;
    for (int j = 0; j < height; ++j)
        for (int i = 0; i < width; ++i) {
            // Not "<=": a NaN spread is refined too, so that the second pass decides.
            if (spread[std::size_t(j) * width + i] <= m_adaptive.threshold) continue;
            for (int y = std::max(0, j - reach); y <= std::min(height - 1, j + reach); ++y)
                for (int x = std::max(0, i - reach); x <= std::min(width - 1, i + reach); ++x)
                    refine[std::size_t(y) * width + x] = 1;
        }
    return refine;
}

Texture Renderer::renderImage() {
    const int width = m_camera.width();
    const int height = m_camera.height();
    Texture image(width, height);
    const std::vector<Tile> tiles = makeTiles(width, height);
    const bool centreOnly = m_nbPixelSamples == 1 && m_sampler == SamplerKind::Center;
    const bool adaptive = m_sampler == SamplerKind::Adaptive;
    const SamplerKind kind = adaptive ? m_adaptive.within : m_sampler;
    const auto start = std::chrono::steady_clock::now();
    m_stats = RenderStats{};
    m_refined.clear();
    std::vector<float> spread(adaptive ? std::size_t(width) * std::size_t(height) : 0);

    m_stats.randomNumbers = forEachTile(tiles, m_threads, m_progress, [&](const Tile& tile, std::uint64_t& drawn) {
        // Adaptive: renderPixel sees the integrator through this worker's probe.
        SpreadProbe probe(m_integrator);
        Renderer probed(m_scene, m_camera, probe);
        probed.m_nbPixelSamples = m_nbPixelSamples;
        for (int j = tile.y0; j < tile.y1; ++j)
            for (int i = tile.x0; i < tile.x1; ++i) {
                if (centreOnly) {
                    image.setPixel(i, j, renderPixelCentre(i, j));
                    continue;
                }
                PixelSampler sampler(kind, m_nbPixelSamples, m_seed, i, j, width);
                if (adaptive) {
                    probe.reset();
                    image.setPixel(i, j, probed.renderPixel(i, j, sampler));
                    spread[std::size_t(j) * width + i] = probe.spread();
                } else {
                    image.setPixel(i, j, renderPixel(i, j, sampler));
                }
                drawn += sampler.randomNumbersDrawn();
            }
    });
    m_stats.primaryRays = std::uint64_t(width) * std::uint64_t(height) * std::uint64_t(centreOnly ? 1 : m_nbPixelSamples);

    if (adaptive) {
        m_refined = pixelsToRefine(spread);
        const std::vector<std::uint8_t>& refine = m_refined;
        m_stats.refinedPixels = std::uint64_t(std::count(refine.begin(), refine.end(), std::uint8_t(1)));
        m_stats.randomNumbers += forEachTile(tiles, m_threads, m_progress, [&](const Tile& tile, std::uint64_t& drawn) {
            Renderer more(m_scene, m_camera, m_integrator);
            more.m_nbPixelSamples = m_adaptive.maxSamples;
            for (int j = tile.y0; j < tile.y1; ++j)
                for (int i = tile.x0; i < tile.x1; ++i) {
                    if (!refine[std::size_t(j) * width + i]) continue;
                    PixelSampler sampler(kind, m_adaptive.maxSamples, secondPassSeed(m_seed), i, j, width);
                    image.setPixel(i, j, more.renderPixel(i, j, sampler));
                    drawn += sampler.randomNumbersDrawn();
                }
        });
        m_stats.primaryRays += m_stats.refinedPixels * std::uint64_t(m_adaptive.maxSamples);
    }
    m_stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return image;
}

} // namespace raylab
