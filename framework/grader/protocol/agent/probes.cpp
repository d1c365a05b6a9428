#include "grader/protocol/agent/probes.h"

#include "raylab/gradient.h"
#include "raylab/integrator.h"
#include "raylab/perspective_camera.h"
#include "raylab/renderer.h"

#include <mutex>
#include <stdexcept>
#include <utility>

namespace raylab::agent {

using grader::protocol::Call;
using grader::protocol::Probe;

namespace {

// Reads the inputs in order, as the student's functions take them (float, int).
class Inputs {
public:
    explicit Inputs(const std::vector<double>& values) : m_numbers(values) {}
    double number() { return m_numbers.number(); }
    float real() { return float(number()); }
    int integer() { return int(number()); }
    glm::vec3 vec3() { return glm::vec3(m_numbers.vec3()); }

private:
    grader::protocol::NumberReader m_numbers;
};

void append(std::vector<double>& out, const glm::vec3& v) {
    out.insert(out.end(), {v.x, v.y, v.z});
}

std::vector<double> fillGradientProbe(Inputs in) {
    const int width = in.integer(), height = in.integer();
    Texture t(width, height);
    for (int j = 0; j < height; ++j) // a pixel never written stays visible
        for (int i = 0; i < width; ++i)
            t.setPixel(i, j, Color(-1.f));
    fillGradient(t);
    std::vector<double> out;
    for (int j = 0; j < height; ++j)
        for (int i = 0; i < width; ++i)
            append(out, t.getPixel(i, j));
    return out;
}

std::vector<double> viewportProbe(Inputs in) {
    const int width = in.integer(), height = in.integer();
    const PerspectiveCamera camera(width, height, in.real());
    std::vector<double> out{camera.viewportHeight(), camera.viewportWidth()};
    append(out, camera.topLeft());
    return out;
}

std::vector<double> generateRayProbe(Inputs in) {
    const int width = in.integer(), height = in.integer();
    const float fovy = in.real();
    const PerspectiveCamera camera(width, height, in.vec3(), fovy);
    const float sx = in.real();
    const Ray ray = camera.generateRay(sx, in.real());
    std::vector<double> out;
    append(out, ray.origin);
    append(out, ray.direction);
    return out;
}

SphereGeometry sphere(Inputs& in, const Color& colour = Color(1.f)) {
    const glm::vec3 centre = in.vec3();
    return SphereGeometry(centre, in.real(), colour);
}

Ray ray(Inputs& in) {
    const glm::vec3 origin = in.vec3();
    return Ray{origin, in.vec3()};
}

std::vector<double> intersectProbe(Inputs in) {
    const SphereGeometry s = sphere(in);
    const Ray r = ray(in);
    const float tMin = in.real(), tMax = in.real();
    HitRecord hit;
    hit.t = -7.f; // a miss must leave it alone
    const bool found = s.intersect(r, tMin, tMax, hit);
    std::vector<double> out{found ? 1. : 0., hit.t};
    append(out, hit.position);
    return out;
}

std::vector<double> normalProbe(Inputs in) {
    const SphereGeometry s = sphere(in);
    std::vector<double> out;
    append(out, s.computeNormal(in.vec3()));
    return out;
}

std::vector<double> liProbe(Inputs in) {
    const int shading = in.integer();
    if (shading < 0 || shading > 2) throw std::invalid_argument("probe Li: no shading " + std::to_string(shading));
    const glm::vec3 centre = in.vec3();
    const float radius = in.real();
    const Color colour = in.vec3();
    Scene scene;
    scene.spheres.emplace_back(centre, radius, colour);
    scene.background = in.vec3();
    const RayCastIntegrator integrator{Shading(shading)};
    std::vector<double> out;
    append(out, integrator.Li(scene, ray(in)));
    return out;
}

std::vector<double> lookAtProbe(Inputs in) {
    const int width = in.integer(), height = in.integer();
    const glm::vec3 position = in.vec3(), target = in.vec3(), up = in.vec3();
    const float fovy = in.real();
    // Built first elsewhere, then rebuilt: nothing may survive from the first frame.
    PerspectiveCamera camera(width, height, position + glm::vec3(3.f, -2.f, 1.f), position, glm::vec3(0.f, 1.f, 0.f),
                             fovy);
    camera = PerspectiveCamera(width, height, position, target, up, fovy);
    std::vector<double> out;
    for (const glm::vec3& v : {camera.u(), camera.v(), camera.w(), camera.position()})
        append(out, v);
    out.insert(out.end(), {camera.viewportHeight(), camera.viewportWidth()});
    append(out, camera.topLeft());
    return out;
}

std::vector<double> lookAtRefusedProbe(Inputs in) {
    const glm::vec3 position = in.vec3(), target = in.vec3(), up = in.vec3();
    try {
        const PerspectiveCamera camera(200, 100, position, target, up, 60.f);
        return {0.};
    } catch (const std::invalid_argument&) {
        return {1.};
    }
}

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

std::vector<double> setSamplesProbe(Inputs in) {
    const Scene scene;
    const RecordingCamera camera(4, 4);
    const PointIntegrator integrator;
    Renderer renderer(scene, camera, integrator);
    bool refused = false;
    try {
        renderer.setNbPixelSamples(in.integer());
    } catch (const std::invalid_argument&) {
        refused = true;
    }
    return {refused ? 1. : 0., double(renderer.nbPixelSamples())};
}

std::vector<double> renderPixelProbe(Inputs in) {
    const int width = in.integer(), height = in.integer(), i = in.integer(), j = in.integer(), n = in.integer();
    const auto seed = std::uint64_t(in.number());
    const Scene scene;
    const RecordingCamera camera(width, height);
    const PointIntegrator integrator;
    Renderer renderer(scene, camera, integrator);
    renderer.setNbPixelSamples(n);
    PixelSampler sampler(SamplerKind::Random, n, seed, i, j, width);
    const Color colour = renderer.renderPixel(i, j, sampler);
    std::vector<double> out{double(camera.points.size())};
    append(out, colour);
    for (const auto& [sx, sy] : camera.points)
        out.insert(out.end(), {sx, sy});
    return out;
}

} // namespace

std::vector<double> callProbe(const Call& call) {
    const Inputs in(call.inputs);
    switch (call.probe) {
    case Probe::FillGradient: return fillGradientProbe(in);
    case Probe::Viewport: return viewportProbe(in);
    case Probe::GenerateRay: return generateRayProbe(in);
    case Probe::Intersect: return intersectProbe(in);
    case Probe::ComputeNormal: return normalProbe(in);
    case Probe::Li: return liProbe(in);
    case Probe::LookAt: return lookAtProbe(in);
    case Probe::LookAtRefused: return lookAtRefusedProbe(in);
    case Probe::SetSamples: return setSamplesProbe(in);
    case Probe::RenderPixel: return renderPixelProbe(in);
    }
    throw std::invalid_argument("unknown probe");
}

} // namespace raylab::agent
