#include "grader/judge/reference_render.h"

#include "grader/judge/compare.h"

#include "src/figure.h"
#include "src/parallel.h"
#include "src/shadow_rays.h"

#include <glm/common.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace raylab::grader {

namespace {

// How far from the centre ray a neighbour ray of ambiguousPixels is, in pixels.
constexpr float kAmbiguity = 2e-3f;

// How far off its surface, in float spacings at its scale, ambiguousPixels moves the point a shadow
// ray leaves, on each side: a few times the rounding of a hit point (half a spacing per coordinate,
// plus t's own few ulps), so that it covers any correct formula upstream (docs/grading.md).
constexpr float kOffSurfaceUlps = 4.f;

// While alive, the shadow rays of this thread leave their points moved off their surfaces (src/shadow_rays.h).
class ShadowOriginsMoved {
public:
    explicit ShadowOriginsMoved(float ulps) { setShadowOriginOffsetOnThisThread(ulps); }
    ~ShadowOriginsMoved() { setShadowOriginOffsetOnThisThread(0.f); }
    ShadowOriginsMoved(const ShadowOriginsMoved&) = delete;
    ShadowOriginsMoved& operator=(const ShadowOriginsMoved&) = delete;
};

// The rays of a figure, as every render of it sees them (figure.h's SceneRender).
class FigureRays {
public:
    explicit FigureRays(const SceneDescription& d) : m_render(d), m_width(float(d.width)), m_height(float(d.height)) {}
    // The colour at (x, y) in pixels from the image's top-left corner.
    Color at(float x, float y) const {
        return m_render.integrator().Li(m_render.scene(), m_render.camera().generateRay(x / m_width, y / m_height));
    }

private:
    SceneRender m_render;
    float m_width, m_height;
};

bool differ(const Color& a, const Color& b) {
    for (int k = 0; k < 3; ++k)
        if (std::abs(int(toByte(a[k])) - int(toByte(b[k]))) > 1) return true;
    return false;
}

// A pixel is ambiguous when its colour changes by more than 1 LSB under rays a rounding apart from
// the reference's: its centre ray moved by kAmbiguity (a silhouette, a shadow's edge, a grazing hit
// through the pixel's centre), or its shadow rays leaving from points kOffSurfaceUlps off their
// surfaces, either side (a shadow ray that grazes the surface it leaves: the terminator of a sphere
// lit from the side, where one correct lab's hit point shadows itself and another's does not).
bool ambiguousAt(const FigureRays& rays, int i, int j) {
    const float x = float(i) + 0.5f, y = float(j) + 0.5f;
    const Color centre = rays.at(x, y);
    for (float dx : {-kAmbiguity, 0.f, kAmbiguity})
        for (float dy : {-kAmbiguity, 0.f, kAmbiguity})
            if (differ(rays.at(x + dx, y + dy), centre)) return true;
    for (float ulps : {-kOffSurfaceUlps, kOffSurfaceUlps}) {
        const ShadowOriginsMoved moved(ulps);
        if (differ(rays.at(x, y), centre)) return true;
    }
    return false;
}

struct Moments {
    glm::dvec3 mean{0.};
    glm::dvec3 variance{0.};
};

// The mean and variance of the colours at the centres of an n x n grid of pixel (i, j)'s cells.
Moments gridMoments(const FigureRays& rays, int i, int j, int n) {
    glm::dvec3 sum(0.), sumSq(0.);
    for (int b = 0; b < n; ++b)
        for (int a = 0; a < n; ++a) {
            const glm::dvec3 c(rays.at(float(i) + (float(a) + 0.5f) / float(n), float(j) + (float(b) + 0.5f) / float(n)));
            sum += c;
            sumSq += c * c;
        }
    Moments m;
    m.mean = sum / double(n * n);
    m.variance = glm::max(sumSq / double(n * n) - m.mean * m.mean, glm::dvec3(0.));
    return m;
}

// A pixel that the silhouette only grazes can look constant on a coarse grid: a pixel is constant
// only when its neighbours' centres agree with its own too.
std::vector<std::uint8_t> neighboursDiffer(const SceneDescription& d, const FigureRays& rays, int threads) {
    std::vector<Color> centres(std::size_t(d.width) * d.height);
    parallelFor(std::size_t(d.height), threads, false, [&](std::size_t j, unsigned) {
        for (int i = 0; i < d.width; ++i) centres[j * d.width + i] = rays.at(float(i) + 0.5f, float(j) + 0.5f);
    });
    std::vector<std::uint8_t> differ(centres.size(), 0);
    for (int j = 0; j < d.height; ++j)
        for (int i = 0; i < d.width; ++i) {
            const Color& c = centres[std::size_t(j) * d.width + i];
            for (int y = std::max(0, j - 1); y <= std::min(d.height - 1, j + 1); ++y)
                for (int x = std::max(0, i - 1); x <= std::min(d.width - 1, i + 1); ++x)
                    if (centres[std::size_t(y) * d.width + x] != c) differ[std::size_t(j) * d.width + i] = 1;
        }
    return differ;
}

Image8 renderImage8(const SceneDescription& d, int threads) {
    const FigureResult r = renderScene(d, RenderOptions{threads, false});
    if (r.status != FigureResult::Status::Rendered) throw std::runtime_error(d.id + " does not render from the reference: " + r.message);
    std::uint64_t nonFinite = 0;
    Image8 image = quantize(*r.image, &nonFinite);
    if (nonFinite) throw std::runtime_error(d.id + ": the reference has NaN pixels");
    return image;
}

double rmse(const Image8& image, const std::vector<float>& mean) {
    double sumSq = 0.;
    for (std::size_t k = 0; k < image.rgb.size(); ++k) {
        const double e = double(image.rgb[k]) - mean[k];
        sumSq += e * e;
    }
    return std::sqrt(sumSq / double(image.rgb.size()));
}

// Renders the figure with 20 seeds: the worst RMSE of a correct render sets the limit; returns the
// other statistics of those renders.
StatisticalMargins measureRmseLimit(const SceneDescription& d, FigureReference& f, int threads) {
    std::vector<Image8> renders;
    SceneDescription seeded = d;
    double worst = 0.;
    for (int seed = 1; seed <= 20; ++seed) {
        seeded.seed = std::uint64_t(seed) * 7919u;
        renders.push_back(renderImage8(seeded, threads));
        worst = std::max(worst, rmse(renders.back(), f.stats->mean));
    }
    f.stats->worstCorrectRmse = worst;
    f.stats->rmseLimit = 1.25 * worst;
    StatisticalMargins margins;
    for (const Image8& image : renders)
        for (const auto& [name, value] : compareStatistical(f, image).metrics) {
            if (name == "mean signed difference (LSB)") margins.worstBias = std::max(margins.worstBias, std::abs(value));
            if (name == "allowed |mean signed difference| (LSB)") margins.biasLimit = value;
            if (name == "pixels with |z| > 6") margins.worstOutliers = std::max(margins.worstOutliers, value);
        }
    return margins;
}

} // namespace

bool isStatistical(const SceneDescription& d) { return d.samples > 1 && d.sampler != SamplerKind::Center; }

RenderedReference renderReference(const SceneDescription& d, int lab, int threads) {
    const auto start = std::chrono::steady_clock::now();
    RenderedReference rendered{FigureReference{d.id, lab, renderImage8(d, threads), {}, {}}, {}};
    FigureReference& f = rendered.reference;
    f.renderSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (isStatistical(d)) {
        f.stats = convergedStatistics(d, threads);
        rendered.margins = measureRmseLimit(d, f, threads);
    } else if (!isRegisteredImage(d.shading)) {
        f.ambiguous = ambiguousPixels(d, threads);
    }
    return rendered;
}

std::vector<std::pair<int, int>> ambiguousPixels(const SceneDescription& d, int threads) {
    const FigureRays rays(d);
    std::vector<std::uint8_t> flag(std::size_t(d.width) * d.height, 0);
    parallelFor(std::size_t(d.height), threads, false, [&](std::size_t j, unsigned) {
        for (int i = 0; i < d.width; ++i) flag[j * d.width + i] = ambiguousAt(rays, i, int(j));
    });
    std::vector<std::pair<int, int>> pixels;
    for (int j = 0; j < d.height; ++j)
        for (int i = 0; i < d.width; ++i)
            if (flag[std::size_t(j) * d.width + i]) pixels.emplace_back(i, j);
    return pixels;
}

double expectedByte(double m, double sd) {
    if (sd < 1e-3) return std::clamp(std::round(m), 0., 255.);
    auto cdf = [&](double x) { return 0.5 * std::erfc(-(x - m) / (sd * std::sqrt(2.))); };
    double expected = 0.;
    const int low = std::max(0, int(std::floor(m - 8. * sd)) - 1), high = std::min(255, int(std::ceil(m + 8. * sd)) + 1);
    for (int k = low; k <= high; ++k) {
        const double below = k == 0 ? 0. : cdf(k - 0.5), above = k == 255 ? 1. : cdf(k + 0.5);
        expected += k * (above - below);
    }
    return expected;
}

// A grid of 4 x 4 points finds the pixels that vary, which then take a 32 x 32 grid.
StatisticalReference convergedStatistics(const SceneDescription& d, int threads) {
    const FigureRays rays(d);
    StatisticalReference s;
    s.samples = d.samples;
    s.mean.resize(std::size_t(d.width) * d.height * 3);
    s.sampleSd.resize(s.mean.size());
    const std::vector<std::uint8_t> differ = neighboursDiffer(d, rays, threads);
    parallelFor(std::size_t(d.height), threads, false, [&](std::size_t j, unsigned) {
        for (int i = 0; i < d.width; ++i) {
            const std::size_t pixel = j * d.width + i;
            Moments m = gridMoments(rays, i, int(j), 4);
            if (m.variance.x + m.variance.y + m.variance.z > 0. || differ[pixel]) m = gridMoments(rays, i, int(j), 32);
            for (int k = 0; k < 3; ++k) {
                const std::size_t index = 3 * pixel + k;
                s.sampleSd[index] = float(255. * std::sqrt(m.variance[k]));
                s.mean[index] = float(expectedByte(255. * m.mean[k], s.sampleSd[index] / std::sqrt(double(d.samples))));
            }
        }
    });
    return s;
}

} // namespace raylab::grader
