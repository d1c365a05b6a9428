// Lab 5's probes, in the agent: the sample count, and renderPixel with a camera that records the
// screen points it is asked for.
#include "grader/protocol/agent/probes.h"
#include "probes.h"

#include "raylab/renderer.h"

#include <mutex>
#include <stdexcept>
#include <utility>

namespace raylab::agent {

namespace {

namespace probes = grader::probes;

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

probes::SampleCount setSamplesProbe(int samples) {
    const Scene scene;
    const RecordingCamera camera(4, 4);
    const PointIntegrator integrator;
    Renderer renderer(scene, camera, integrator);
    bool refused = false;
    try {
        renderer.setNbPixelSamples(samples);
    } catch (const std::invalid_argument&) {
        refused = true;
    }
    return {refused, renderer.nbPixelSamples()};
}

probes::Rendered renderPixelProbe(int width, int height, int i, int j, int samples, double seed) {
    const Scene scene;
    const RecordingCamera camera(width, height);
    const PointIntegrator integrator;
    Renderer renderer(scene, camera, integrator);
    renderer.setNbPixelSamples(samples);
    PixelSampler sampler(SamplerKind::Random, samples, std::uint64_t(seed), i, j, width);
    probes::Rendered rendered{renderer.renderPixel(i, j, sampler), {}};
    for (const auto& [sx, sy] : camera.points)
        rendered.points.push_back({sx, sy});
    return rendered;
}

} // namespace

RAYLAB_REGISTER_PROBE(grader::probes::setSamples, setSamplesProbe);
RAYLAB_REGISTER_PROBE(grader::probes::renderPixel, renderPixelProbe);

} // namespace raylab::agent
