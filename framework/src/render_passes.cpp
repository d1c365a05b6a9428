#include "src/render_passes.h"

#include "src/parallel.h"
#include "src/shadow_rays.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <utility>

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

RenderPasses::RenderPasses(Renderer& renderer)
    : m_renderer(renderer), m_width(renderer.m_camera.width()), m_height(renderer.m_camera.height()),
      m_pixels(pixelCount(m_width, m_height), Color(0.f)) {}

Texture RenderPasses::render(Renderer& renderer) {
    RenderPasses passes(renderer);
    if (renderer.m_settings.sampler == SamplerKind::Adaptive) passes.renderAdaptive();
    else if (renderer.m_nbPixelSamples == 1 && renderer.m_settings.sampler == SamplerKind::Center) passes.renderCentres();
    else passes.renderSampled();
    return Texture(passes.m_width, passes.m_height, std::move(passes.m_pixels));
}

template <class Pixel>
std::uint64_t RenderPasses::forEachPixel(const Renderer& renderer, int x0, int y0, int x1, int y1, const Pixel& pixel) {
    if (renderer.m_camera.lab() != nullptr && renderer.m_integrator.lab() != nullptr)
        return forEachPixelDirect(renderer, x0, y0, x1, y1, pixel);
    return sumOverPixels(renderer, x0, y0, x1, y1, pixel);
}

// Every call in it is inlined (flatten; across files by link-time optimisation), lab 5's renderPixel
// too, and `direct` never leaves it: the compiler sees that its handles are direct, so lab 5's
// sample loop keeps no test nor virtual call, and its sum and counter stay in registers.
template <class Pixel>
RAYLAB_FLATTEN std::uint64_t RenderPasses::forEachPixelDirect(const Renderer& renderer, int x0, int y0, int x1, int y1,
                                                              const Pixel& pixel) {
    // The camera copied onto this stack: a store into the image cannot change it, so the compiler
    // need not load its fields again at every pixel (docs/performance.md: 25 instructions a pixel).
    const PerspectiveCamera camera = *renderer.m_camera.lab();
    Renderer direct = renderer;
    direct.m_camera = CameraHandle(camera);
    direct.m_integrator = IntegratorHandle(*renderer.m_integrator.lab());
    return sumOverPixels(direct, x0, y0, x1, y1, pixel);
}

Color RenderPasses::renderPixelCentre(const Renderer& renderer, int i, int j) {
    const float sx = (float(i) + 0.5f) / float(renderer.m_camera.width());
    const float sy = (float(j) + 0.5f) / float(renderer.m_camera.height());
    return renderer.m_integrator.Li(renderer.m_scene, renderer.m_camera.generateRay(sx, sy));
}

Renderer RenderPasses::passRenderer(const Integrator& integrator, int nbSamples) const {
    Renderer pass(m_renderer.m_scene, m_renderer.m_camera, integrator);
    // A new renderer averages 1 sample: lab 5's setter is only asked for more.
    if (nbSamples != 1) pass.setNbPixelSamples(nbSamples);
    return pass;
}

std::vector<std::uint8_t> RenderPasses::pixelsToRefine(const std::vector<float>& spread) const {
    const int width = m_width, height = m_height;
    const AdaptiveSettings& adaptive = m_renderer.m_settings.adaptive;
    std::vector<std::uint8_t> refine(spread.size(), 0);
    const int reach = adaptive.widen ? 1 : 0;
    for (int j = 0; j < height; ++j)
        for (int i = 0; i < width; ++i) {
            // Not "<=": a NaN spread is refined too, so that the second pass decides.
            if (spread[std::size_t(j) * width + i] <= adaptive.threshold) continue;
            for (int y = std::max(0, j - reach); y <= std::min(height - 1, j + reach); ++y)
                for (int x = std::max(0, i - reach); x <= std::min(width - 1, i + reach); ++x)
                    refine[std::size_t(y) * width + x] = 1;
        }
    return refine;
}

void RenderPasses::renderCentres() {
    const Renderer& r = m_renderer;
    const RenderSettings& settings = r.m_settings;
    const int width = m_width;
    Color* const pixels = m_pixels.data();
    const TileCounts counts = forEachTile(makeTiles(width, m_height), settings.threads, settings.progress, [&](const Tile& tile, unsigned) {
        return forEachPixel(r, tile.x0, tile.y0, tile.x1, tile.y1, [&](const Renderer& renderer, int i, int j) {
            pixels[std::size_t(j) * width + i] = renderPixelCentre(renderer, i, j);
            return std::uint64_t(0);
        });
    });
    m_renderer.m_stats.shadowRays = counts.shadowRays;
    m_renderer.m_stats.primaryRays = pixelCount(width, m_height);
}

void RenderPasses::renderSampled() {
    const Renderer& r = m_renderer;
    const RenderSettings& settings = r.m_settings;
    const int width = m_width;
    Color* const pixels = m_pixels.data();
    const TileCounts counts = forEachTile(makeTiles(width, m_height), settings.threads, settings.progress, [&](const Tile& tile, unsigned) {
        return forEachPixel(r, tile.x0, tile.y0, tile.x1, tile.y1, [&](const Renderer& renderer, int i, int j) {
            PixelSampler sampler(settings.sampler, r.m_nbPixelSamples, settings.seed, i, j, width);
            pixels[std::size_t(j) * width + i] = renderer.renderPixel(i, j, sampler);
            return sampler.randomNumbersDrawn();
        });
    });
    RenderStats& stats = m_renderer.m_stats;
    stats.randomNumbers = counts.randomNumbers;
    stats.shadowRays = counts.shadowRays;
    stats.primaryRays = pixelCount(width, m_height) * std::uint64_t(r.m_nbPixelSamples);
}

void RenderPasses::renderAdaptive() {
    Renderer& r = m_renderer;
    const RenderSettings& settings = r.m_settings;
    const int width = m_width;
    Color* const pixels = m_pixels.data();
    const std::vector<Tile> tiles = makeTiles(width, m_height);
    const SamplerKind kind = settings.adaptive.within;
    const int nbSamples = r.m_nbPixelSamples, maxSamples = settings.adaptive.maxSamples;

    // First pass: each worker sees the integrator through a probe of its own.
    const unsigned workers = workerCount(settings.threads, tiles.size());
    std::vector<SpreadProbe> probes(workers, SpreadProbe(r.m_integrator));
    std::vector<Renderer> probed;
    for (const SpreadProbe& probe : probes) probed.push_back(passRenderer(probe, nbSamples));
    std::vector<float> spread(pixelCount(width, m_height));
    const TileCounts first = forEachTile(tiles, settings.threads, settings.progress, [&](const Tile& tile, unsigned worker) {
        std::uint64_t drawn = 0;
        for (int j = tile.y0; j < tile.y1; ++j)
            for (int i = tile.x0; i < tile.x1; ++i) {
                PixelSampler sampler(kind, nbSamples, settings.seed, i, j, width);
                probes[worker].reset();
                pixels[std::size_t(j) * width + i] = probed[worker].renderPixel(i, j, sampler);
                spread[std::size_t(j) * width + i] = probes[worker].spread();
                drawn += sampler.randomNumbersDrawn();
            }
        return drawn;
    });
    RenderStats& stats = r.m_stats;
    stats.randomNumbers = first.randomNumbers;
    stats.shadowRays = first.shadowRays;
    stats.primaryRays = pixelCount(width, m_height) * std::uint64_t(nbSamples);

    // Second pass: the pixels to refine, with new samples that replace the first ones.
    r.m_refined = pixelsToRefine(spread);
    const std::vector<std::uint8_t>& refined = r.m_refined;
    stats.refinedPixels = std::uint64_t(std::count(refined.begin(), refined.end(), std::uint8_t(1)));
    const Renderer more = passRenderer(r.m_integrator, maxSamples);
    const TileCounts second = forEachTile(tiles, settings.threads, settings.progress, [&](const Tile& tile, unsigned) {
        return forEachPixel(more, tile.x0, tile.y0, tile.x1, tile.y1, [&](const Renderer& renderer, int i, int j) {
            if (!refined[std::size_t(j) * width + i]) return std::uint64_t(0);
            PixelSampler sampler(kind, maxSamples, secondPassSeed(settings.seed), i, j, width);
            pixels[std::size_t(j) * width + i] = renderer.renderPixel(i, j, sampler);
            return sampler.randomNumbersDrawn();
        });
    });
    stats.randomNumbers += second.randomNumbers;
    stats.shadowRays += second.shadowRays;
    stats.primaryRays += stats.refinedPixels * std::uint64_t(maxSamples);
}

} // namespace raylab
