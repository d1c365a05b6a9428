#include "raylab/renderer.h"

#include "src/parallel.h"
#include "src/shadow_rays.h"

#include <glm/common.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>

// Inline every call in a function, as deep as it goes (GCC, Clang).
#if defined(__GNUC__)
#define RAYLAB_FLATTEN [[gnu::flatten]]
#else
#define RAYLAB_FLATTEN
#endif

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

// What the tiles of one pass counted.
struct TileCounts {
    std::uint64_t randomNumbers = 0; // drawn by the pixel samplers
    std::uint64_t shadowRays = 0;    // traced by the integrator (src/shadow_rays.h)
};

// Runs work(tile, worker) for every tile on the renderer's threads (parallel.h); work returns the
// random numbers its pixel samplers drew. Counts those and the shadow rays the tiles traced.
TileCounts forEachTile(const std::vector<Tile>& tiles, int threads, bool progress,
                       const std::function<std::uint64_t(const Tile&, unsigned worker)>& work) {
    std::vector<TileCounts> counts(workerCount(threads, tiles.size()));
    parallelFor(tiles.size(), threads, progress, [&](std::size_t t, unsigned worker) {
        const std::uint64_t shadowRaysBefore = shadowRaysTracedByThisThread();
        counts[worker].randomNumbers += work(tiles[t], worker);
        counts[worker].shadowRays += shadowRaysTracedByThisThread() - shadowRaysBefore;
    });
    TileCounts total;
    for (const TileCounts& c : counts) {
        total.randomNumbers += c.randomNumbers;
        total.shadowRays += c.shadowRays;
    }
    return total;
}

std::uint64_t pixelCount(int width, int height) { return std::uint64_t(width) * std::uint64_t(height); }

// The sum of pixel(renderer, i, j) over the pixels [x0, x1) x [y0, y1).
template <class Pixel>
std::uint64_t sumOverPixels(const Renderer& renderer, int x0, int y0, int x1, int y1, const Pixel& pixel) {
    std::uint64_t sum = 0;
    for (int j = y0; j < y1; ++j)
        for (int i = x0; i < x1; ++i) sum += pixel(renderer, i, j);
    return sum;
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
    IntegratorHandle m_inner; // lab 3's integrator called directly
    mutable Color m_lo{INFINITY};
    mutable Color m_hi{-INFINITY};
};

// The seed of adaptive sampling's second pass: new samples, not the first pass's again.
std::uint64_t secondPassSeed(std::uint64_t seed) { return seed ^ 0x9e3779b97f4a7c15ull; }

} // namespace

Renderer::Renderer(const Scene& scene, const BaseCamera& camera, const Integrator& integrator)
    : m_scene(scene), m_camera(camera), m_integrator(integrator) {}

Renderer::Renderer(const Renderer& settings, const PerspectiveCamera& camera, const RayCastIntegrator& integrator)
    : m_scene(settings.m_scene), m_camera(camera), m_integrator(integrator), m_nbPixelSamples(settings.m_nbPixelSamples),
      m_sampler(settings.m_sampler), m_seed(settings.m_seed), m_adaptive(settings.m_adaptive),
      m_threads(settings.m_threads), m_progress(settings.m_progress) {}

template <class Pixel>
std::uint64_t Renderer::forEachPixel(int x0, int y0, int x1, int y1, const Pixel& pixel) const {
    if (m_camera.lab() != nullptr && m_integrator.lab() != nullptr)
        return forEachPixelDirect(x0, y0, x1, y1, pixel);
    return sumOverPixels(*this, x0, y0, x1, y1, pixel);
}

// Every call in it is inlined (flatten; across files by link-time optimisation), lab 5's renderPixel
// too, and `direct` never leaves it: the compiler sees that its handles are direct, so lab 5's
// sample loop keeps no test nor virtual call, and its sum and counter stay in registers.
template <class Pixel>
RAYLAB_FLATTEN std::uint64_t Renderer::forEachPixelDirect(int x0, int y0, int x1, int y1, const Pixel& pixel) const {
    // The camera copied onto this stack: a store into the image cannot change it, so the compiler
    // need not load its fields again at every pixel (docs/performance.md: 25 instructions a pixel).
    const PerspectiveCamera camera = *m_camera.lab();
    const Renderer direct(*this, camera, *m_integrator.lab());
    return sumOverPixels(direct, x0, y0, x1, y1, pixel);
}

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

Renderer Renderer::passRenderer(const Integrator& integrator, int nbSamples) const {
    Renderer pass(m_scene, m_camera, integrator);
    // A new renderer averages 1 sample: lab 5's setter is only asked for more.
    if (nbSamples != 1) pass.setNbPixelSamples(nbSamples);
    return pass;
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

void Renderer::renderCentres(Texture& image) {
    m_stats.shadowRays = forEachTile(makeTiles(image.width(), image.height()), m_threads, m_progress, [&](const Tile& tile, unsigned) {
        return forEachPixel(tile.x0, tile.y0, tile.x1, tile.y1, [&](const Renderer& renderer, int i, int j) {
            image.setPixelInside(i, j, renderer.renderPixelCentre(i, j));
            return std::uint64_t(0);
        });
    }).shadowRays;
    m_stats.primaryRays = pixelCount(image.width(), image.height());
}

void Renderer::renderSampled(Texture& image) {
    const int width = image.width();
    const TileCounts counts = forEachTile(makeTiles(width, image.height()), m_threads, m_progress, [&](const Tile& tile, unsigned) {
        return forEachPixel(tile.x0, tile.y0, tile.x1, tile.y1, [&](const Renderer& renderer, int i, int j) {
            PixelSampler sampler(m_sampler, m_nbPixelSamples, m_seed, i, j, width);
            image.setPixelInside(i, j, renderer.renderPixel(i, j, sampler));
            return sampler.randomNumbersDrawn();
        });
    });
    m_stats.randomNumbers = counts.randomNumbers;
    m_stats.shadowRays = counts.shadowRays;
    m_stats.primaryRays = pixelCount(width, image.height()) * std::uint64_t(m_nbPixelSamples);
}

void Renderer::renderAdaptive(Texture& image) {
    const int width = image.width();
    const std::vector<Tile> tiles = makeTiles(width, image.height());
    const SamplerKind kind = m_adaptive.within;

    // First pass: each worker sees the integrator through a probe of its own.
    const unsigned workers = workerCount(m_threads, tiles.size());
    std::vector<SpreadProbe> probes(workers, SpreadProbe(m_integrator));
    std::vector<Renderer> probed;
    for (const SpreadProbe& probe : probes) probed.push_back(passRenderer(probe, m_nbPixelSamples));
    std::vector<float> spread(pixelCount(width, image.height()));
    const TileCounts first = forEachTile(tiles, m_threads, m_progress, [&](const Tile& tile, unsigned worker) {
        std::uint64_t drawn = 0;
        for (int j = tile.y0; j < tile.y1; ++j)
            for (int i = tile.x0; i < tile.x1; ++i) {
                PixelSampler sampler(kind, m_nbPixelSamples, m_seed, i, j, width);
                probes[worker].reset();
                image.setPixelInside(i, j, probed[worker].renderPixel(i, j, sampler));
                spread[std::size_t(j) * width + i] = probes[worker].spread();
                drawn += sampler.randomNumbersDrawn();
            }
        return drawn;
    });
    m_stats.randomNumbers = first.randomNumbers;
    m_stats.shadowRays = first.shadowRays;
    m_stats.primaryRays = pixelCount(width, image.height()) * std::uint64_t(m_nbPixelSamples);

    // Second pass: the pixels to refine, with new samples that replace the first ones.
    m_refined = pixelsToRefine(spread);
    m_stats.refinedPixels = std::uint64_t(std::count(m_refined.begin(), m_refined.end(), std::uint8_t(1)));
    const Renderer more = passRenderer(m_integrator, m_adaptive.maxSamples);
    const TileCounts second = forEachTile(tiles, m_threads, m_progress, [&](const Tile& tile, unsigned) {
        return more.forEachPixel(tile.x0, tile.y0, tile.x1, tile.y1, [&](const Renderer& renderer, int i, int j) {
            if (!m_refined[std::size_t(j) * width + i]) return std::uint64_t(0);
            PixelSampler sampler(kind, m_adaptive.maxSamples, secondPassSeed(m_seed), i, j, width);
            image.setPixelInside(i, j, renderer.renderPixel(i, j, sampler));
            return sampler.randomNumbersDrawn();
        });
    });
    m_stats.randomNumbers += second.randomNumbers;
    m_stats.shadowRays += second.shadowRays;
    m_stats.primaryRays += m_stats.refinedPixels * std::uint64_t(m_adaptive.maxSamples);
}

Texture Renderer::renderImage() {
    const auto start = std::chrono::steady_clock::now();
    m_stats = RenderStats{};
    m_refined.clear();
    Texture image(m_camera.width(), m_camera.height());
    if (m_sampler == SamplerKind::Adaptive) renderAdaptive(image);
    else if (m_nbPixelSamples == 1 && m_sampler == SamplerKind::Center) renderCentres(image);
    else renderSampled(image);
    m_stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return image;
}

} // namespace raylab
