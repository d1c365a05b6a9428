// Lab 5's function checks: the sample count and the average, with a camera that counts its rays
// (no image metric can tell 4 stratified samples from 16 random ones; counting can).
#include "checks/check_support.h"

#include "raylab/renderer.h"

#include <atomic>
#include <mutex>
#include <set>
#include <stdexcept>
#include <utility>

using namespace raylab;
using namespace raylab::checks;

namespace {

// Records every screen point it is asked for; its rays carry (sx, sy) in the direction.
class RecordingCamera final : public BaseCamera {
public:
    RecordingCamera(int w, int h) : BaseCamera(w, h) {}
    Ray generateRay(float sx, float sy) const override {
        std::lock_guard lock(m_mutex);
        points.emplace_back(sx, sy);
        return Ray{{0.f, 0.f, 0.f}, {sx, sy, 1.f}};
    }
    mutable std::vector<std::pair<float, float>> points;

private:
    mutable std::mutex m_mutex;
};

// The colour is the screen point itself: the average is the mean of the points asked for.
class PointIntegrator final : public Integrator {
public:
    Color Li(const Scene&, const Ray& ray) const override { return Color(ray.direction.x, ray.direction.y, 1.f); }
};

} // namespace

TEST_SUITE("lab5") {

TEST_CASE("setNbPixelSamples: stores N and refuses fewer than 1") {
    const Scene scene;
    const RecordingCamera camera(4, 4);
    const PointIntegrator integrator;
    Renderer renderer(scene, camera, integrator);
    renderer.setNbPixelSamples(9);
    expectTrue("nbPixelSamples() after setNbPixelSamples(9)", renderer.nbPixelSamples() == 9, "9",
               std::to_string(renderer.nbPixelSamples()), "store the count in m_nbPixelSamples");
    for (int bad : {0, -3}) {
        bool refused = false;
        try {
            renderer.setNbPixelSamples(bad);
        } catch (const std::invalid_argument&) {
            refused = true;
        }
        expectTrue("setNbPixelSamples(" + std::to_string(bad) + ")", refused, "std::invalid_argument",
                   "no exception", "fewer than 1 sample has no meaning: throw std::invalid_argument");
    }
}

TEST_CASE("renderPixel: N rays and their average") {
    const Scene scene;
    const RecordingCamera camera(8, 4);
    const PointIntegrator integrator;
    Renderer renderer(scene, camera, integrator);
    for (int n : {1, 5, 16}) {
        renderer.setNbPixelSamples(n);
        camera.points.clear();
        PixelSampler sampler(SamplerKind::Random, n, 7, 3, 2, 8);
        const Color got = renderer.renderPixel(3, 2, sampler);
        const std::string what = "pixel (3, 2) with " + std::to_string(n) + " samples";
        if (!expectTrue(what + ": rays traced", camera.points.size() == std::size_t(n), std::to_string(n),
                        std::to_string(camera.points.size()), "trace exactly one ray per sample"))
            continue;
        Color mean(0.f);
        for (const auto& [sx, sy] : camera.points) mean += Color(sx, sy, 1.f);
        mean /= float(n);
        expectNear(what + ": the colour", got, mean, 1e-5f,
                   "return the sum of the samples divided by the number of samples (blue is 1 for every sample)");
        bool inside = true;
        for (const auto& [sx, sy] : camera.points) inside = inside && sx >= 3.f / 8.f && sx <= 4.f / 8.f && sy >= 2.f / 4.f && sy <= 3.f / 4.f;
        expectTrue(what + ": screen points", inside, "every (sx, sy) inside the pixel", "a point outside it",
                   "sx = (i + offset.x) / W, sy = (j + offset.y) / H");
    }
}

TEST_CASE("renderPixel: each sample takes its own offset from the sampler") {
    const Scene scene;
    const RecordingCamera camera(8, 8);
    const PointIntegrator integrator;
    Renderer renderer(scene, camera, integrator);
    renderer.setNbPixelSamples(8);
    PixelSampler sampler(SamplerKind::Random, 8, 3, 1, 1, 8);
    renderer.renderPixel(1, 1, sampler);
    const std::set<std::pair<float, float>> distinct(camera.points.begin(), camera.points.end());
    expectTrue("distinct screen points among 8 samples", distinct.size() == 8, "8", std::to_string(distinct.size()),
               "call sampler.next2D() once per sample, inside the loop");
}

} // TEST_SUITE
