// The renderer does only what a scene asks: counted through wrappers of the camera and the
// integrator, the samplers' own count of random numbers, and lab 3's sphere counting its calls.
#include "counting_sphere.h"

#include "raylab/perspective_camera.h"
#include "raylab/renderer.h"

#include <doctest/doctest.h>

#include <atomic>
#include <cmath>
#include <limits>
#include <stdexcept>

using namespace raylab;
using raylab::test::sphereIntersections;
using raylab::test::sphereNormals;

namespace {

constexpr int W = 60, H = 40;
constexpr std::uint64_t kPixels = std::uint64_t(W) * H;

// Counts the primary rays, and those not through a pixel centre.
class CountingCamera final : public BaseCamera {
public:
    explicit CountingCamera(const BaseCamera& inner) : BaseCamera(inner.width(), inner.height()), m_inner(inner) {}
    Ray generateRay(float sx, float sy) const override {
        rays.fetch_add(1, std::memory_order_relaxed);
        const float fx = sx * float(m_width) - 0.5f, fy = sy * float(m_height) - 0.5f;
        if (std::abs(fx - std::round(fx)) > 1e-3f || std::abs(fy - std::round(fy)) > 1e-3f)
            offCentre.fetch_add(1, std::memory_order_relaxed);
        return m_inner.generateRay(sx, sy);
    }
    mutable std::atomic<std::uint64_t> rays{0};
    mutable std::atomic<std::uint64_t> offCentre{0};

private:
    const BaseCamera& m_inner;
};

class CountingIntegrator final : public Integrator {
public:
    explicit CountingIntegrator(const Integrator& inner) : m_inner(inner) {}
    Color Li(const Scene& scene, const Ray& ray) const override {
        calls.fetch_add(1, std::memory_order_relaxed);
        return m_inner.Li(scene, ray);
    }
    mutable std::atomic<std::uint64_t> calls{0};

private:
    const Integrator& m_inner;
};

struct Counts {
    Texture image{1, 1};
    RenderStats stats;
    std::vector<std::uint8_t> refined;
    std::uint64_t rays = 0, offCentre = 0, li = 0, intersections = 0, normals = 0;
};

struct Job {
    Scene scene = makeTp1Scene();
    Shading shading = Shading::Cosine;
    bool directions = false;
    SamplerKind sampler = SamplerKind::Center;
    int samples = 1;
    AdaptiveSettings adaptive;
    int threads = 2;
    std::uint64_t seed = 1;
};

Counts render(const Job& job) {
    const PerspectiveCamera camera(W, H);
    const CountingCamera counting(camera);
    const RayCastIntegrator rayCast(job.shading);
    const DirectionIntegrator directions;
    const CountingIntegrator integrator(job.directions ? static_cast<const Integrator&>(directions) : rayCast);
    Renderer renderer(job.scene, counting, integrator);
    renderer.settings() = RenderSettings{job.sampler, job.seed, job.adaptive, job.threads, false};
    renderer.setNbPixelSamples(job.samples);
    sphereIntersections = 0;
    sphereNormals = 0;
    Counts c;
    c.image = renderer.renderImage();
    c.stats = renderer.stats();
    c.refined = renderer.refinedPixels();
    c.rays = counting.rays;
    c.offCentre = counting.offCentre;
    c.li = integrator.calls;
    c.intersections = sphereIntersections;
    c.normals = sphereNormals;
    return c;
}

// Pixels whose centre sees the sphere of the scene tp1 (its disc is centred, radius 122.47 / 10 px).
bool nearSilhouette(int i, int j, double pixels) {
    const double radius = 122.474487 * W / 600.;
    return std::abs(std::hypot(i + 0.5 - W / 2., j + 0.5 - H / 2.) - radius) < pixels;
}

} // namespace

TEST_SUITE("render work") {

TEST_CASE("one centred sample a pixel: one ray through each centre, no random numbers") {
    const Counts c = render(Job{});
    CHECK(c.rays == kPixels);
    CHECK(c.offCentre == 0);
    CHECK(c.li == kPixels);
    CHECK(c.stats.primaryRays == kPixels);
    CHECK(c.stats.randomNumbers == 0);
}

TEST_CASE("each sampler draws only the random numbers it needs") {
    Job job;
    job.samples = 4;
    for (auto [kind, perPixel] : {std::pair{SamplerKind::Center, 0}, {SamplerKind::Grid, 0}, {SamplerKind::Sobol, 2},
                                  {SamplerKind::R2, 2}, {SamplerKind::Random, 8}, {SamplerKind::Stratified, 8}}) {
        job.sampler = kind;
        const Counts c = render(job);
        INFO(samplerName(kind));
        CHECK(c.rays == 4 * kPixels);
        CHECK(c.stats.primaryRays == 4 * kPixels);
        CHECK(c.stats.randomNumbers == perPixel * kPixels);
    }
}

TEST_CASE("a scene without lights traces no shadow ray, whatever the shading") {
    for (Shading shading : {Shading::Flat, Shading::Cosine}) {
        Job job;
        job.shading = shading;
        CHECK(render(job).stats.shadowRays == 0);
    }
}

TEST_CASE("the shadow test stops at the first object it meets; the nearest hit tries them all") {
    Scene row; // three spheres one behind the other along +z
    for (float z : {3.f, 6.f, 9.f}) row.add(SphereGeometry(glm::vec3(0.f, 0.f, z), 1.f, Color(1.f)));
    const Ray ray{{0.f, 0.f, 0.f}, {0.f, 0.f, 1.f}};
    sphereIntersections = 0;
    CHECK(row.occluded(ray, 1e-4f, 100.f));
    CHECK(sphereIntersections == 1);
    HitRecord hit;
    sphereIntersections = 0;
    CHECK(row.intersect(ray, hit));
    CHECK(sphereIntersections == 3);
    sphereIntersections = 0;
    CHECK_FALSE(row.occluded(ray, 1e-4f, 1.5f)); // the light before the first sphere: every one is tried
    CHECK(sphereIntersections == 3);
}

TEST_CASE("flat shading computes no normal; cosine shading one per hit") {
    Job job;
    job.shading = Shading::Flat;
    const Counts flat = render(job);
    CHECK(flat.intersections == kPixels); // one sphere, one test a ray
    CHECK(flat.normals == 0);
    std::uint64_t hits = 0;
    for (const Color& c : flat.image.pixels()) hits += c != makeTp1Scene().background;
    CHECK(hits > 400);
    job.shading = Shading::Cosine;
    CHECK(render(job).normals == hits);
    job.shading = Shading::PlaceholderNormal;
    CHECK(render(job).normals == 0);
}

TEST_CASE("a scene with no objects intersects nothing; the directions picture looks at no object") {
    Job job;
    job.scene.setAll(std::vector<SphereGeometry>{});
    Counts c = render(job);
    CHECK(c.intersections == 0);
    CHECK(c.li == kPixels);
    job = Job{};
    job.directions = true;
    c = render(job);
    CHECK(c.intersections == 0);
    CHECK(c.normals == 0);
}

TEST_CASE("adaptive: a pixel whose samples agree keeps its first samples") {
    Job job;
    job.sampler = SamplerKind::Adaptive;
    job.samples = 16;
    job.adaptive.threshold = 2.f; // colours are in [0, 1]: no two samples differ by 2
    const Counts adaptive = render(job);
    CHECK(adaptive.stats.refinedPixels == 0);
    CHECK(adaptive.stats.primaryRays == 16 * kPixels);
    job.sampler = SamplerKind::Stratified;
    CHECK(render(job).image.pixels() == adaptive.image.pixels());
}

TEST_CASE("adaptive: more samples only at the silhouette (and one pixel around it), counted exactly") {
    Job job;
    job.shading = Shading::Flat; // so that samples disagree only across the silhouette
    job.sampler = SamplerKind::Adaptive;
    job.samples = 16;
    job.adaptive.maxSamples = 64;
    job.adaptive.threshold = 0.1f;
    job.adaptive.widen = false;
    const Counts narrow = render(job);
    job.adaptive.widen = true;
    const Counts wide = render(job);
    job.sampler = SamplerKind::Stratified;
    const Counts base = render(job);

    std::uint64_t narrowCount = 0, wideCount = 0;
    for (int j = 0; j < H; ++j)
        for (int i = 0; i < W; ++i) {
            const std::size_t k = std::size_t(j) * W + i;
            narrowCount += narrow.refined[k];
            wideCount += wide.refined[k];
            if (narrow.refined[k]) CHECK(nearSilhouette(i, j, 0.75));
            if (wide.refined[k]) CHECK(nearSilhouette(i, j, 2.));
            if (narrow.refined[k]) CHECK(wide.refined[k]);
            // A pixel not rendered again keeps its first samples: the stratified render's value.
            if (!wide.refined[k]) CHECK(wide.image.getPixel(i, j) == base.image.getPixel(i, j));
            // A pixel whose first samples all hit, or all missed, is not rendered again without widening.
            const Color b = base.image.getPixel(i, j);
            if (b == Color(0.f, 0.f, 1.f) || b == Color(0.5f)) CHECK_FALSE(narrow.refined[k]);
            else CHECK(narrow.refined[k]);
        }
    CHECK(narrowCount == narrow.stats.refinedPixels);
    CHECK(wideCount == wide.stats.refinedPixels);
    CHECK(narrowCount > 50);
    CHECK(wideCount > narrowCount + 50);
    CHECK(wide.stats.primaryRays == 16 * kPixels + 64 * wideCount);
    CHECK(wide.li == wide.stats.primaryRays);
    CHECK(wide.rays == wide.stats.primaryRays);
}

TEST_CASE("adaptive: its passes draw the random numbers of the sampler they use, and no more") {
    Job job;
    job.sampler = SamplerKind::Adaptive;
    job.samples = 4;
    job.adaptive.maxSamples = 16;
    job.adaptive.within = SamplerKind::Grid;
    Counts c = render(job);
    CHECK(c.stats.refinedPixels > 0);
    CHECK(c.stats.randomNumbers == 0);
    job.adaptive.within = SamplerKind::Sobol;
    c = render(job);
    CHECK(c.stats.randomNumbers == 2 * (kPixels + c.stats.refinedPixels));
    job.adaptive.within = SamplerKind::Stratified;
    c = render(job);
    CHECK(c.stats.randomNumbers == 2 * (4 * kPixels + 16 * c.stats.refinedPixels));
}

TEST_CASE("adaptive: the same image on any number of threads") {
    Job job;
    job.sampler = SamplerKind::Adaptive;
    job.samples = 4;
    job.adaptive.maxSamples = 32;
    job.threads = 1;
    const Counts one = render(job);
    for (int threads : {2, 3, 5}) {
        job.threads = threads;
        CHECK(render(job).image.pixels() == one.image.pixels());
    }
    job.seed = 2;
    CHECK(render(job).image.pixels() != one.image.pixels());
}

TEST_CASE("settings without a meaning are refused before any pixel is rendered") {
    const Scene scene = makeTp1Scene();
    const PerspectiveCamera camera(W, H);
    const RayCastIntegrator integrator(Shading::Flat);
    const CountingIntegrator counting(integrator);
    Renderer renderer(scene, camera, counting);
    const auto refused = [&](const RenderSettings& settings) {
        renderer.settings() = settings;
        counting.calls = 0;
        CHECK_THROWS_AS(renderer.renderImage(), std::invalid_argument);
        CHECK(counting.calls == 0);
    };
    RenderSettings s;
    s.adaptive.threshold = -1.f;
    refused(s);
    s = RenderSettings{};
    s.adaptive.threshold = std::numeric_limits<float>::quiet_NaN();
    refused(s);
    s = RenderSettings{};
    s.adaptive.maxSamples = 0;
    refused(s);
    s = RenderSettings{};
    s.adaptive.within = SamplerKind::Adaptive;
    refused(s);
    s = RenderSettings{};
    s.threads = -1;
    refused(s);
    renderer.settings() = RenderSettings{};
    CHECK_NOTHROW(renderer.renderImage());
}

}
