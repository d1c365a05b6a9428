#include "src/figure.h"

#include "raylab/integrator_registry.h"
#include "raylab/todo.h"

#include <chrono>
#include <stdexcept>

namespace raylab {

namespace {

// The default camera sits at the world origin, so its render space is world space.
RenderSpace renderSpaceOf(const SceneDescription& d) {
    if (isRegisteredImage(d.shading)) throw std::invalid_argument(d.id + ": " + d.shading + " is drawn without rays");
    return RenderSpace(d.camera.lookAt ? d.camera.position : glm::vec3(0.f));
}

PerspectiveCamera makeCamera(const SceneDescription& d, const RenderSpace& space) {
    const CameraDescription& c = d.camera;
    if (!c.lookAt) return PerspectiveCamera(d.width, d.height, c.fovy);
    checkLookAtParameters(c.position, c.target, c.up);
    return PerspectiveCamera(d.width, d.height, space.toRender(c.position), space.toRender(c.target), c.up, c.fovy);
}

Texture renderWithoutRays(const SceneDescription& d, RenderStats& stats) {
    const auto start = std::chrono::steady_clock::now();
    Texture texture = makeRegisteredImage(d.shading, d.width, d.height);
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return texture;
}

} // namespace

SceneRender::SceneRender(const SceneDescription& d, const RenderOptions& options)
    : m_space(renderSpaceOf(d)), m_scene(m_space.toRender(d.scene)), m_camera(makeCamera(d, m_space)),
      m_integrator(makeRegisteredIntegrator(d.shading, d.shadingParameters)), m_renderer(m_scene, m_camera, *m_integrator) {
    m_renderer.settings() = RenderSettings{d.sampler, d.seed, d.adaptive, options.threads, options.progress};
    // Lab 5's code is only asked for when the scene wants more than one sample.
    if (d.samples != 1) m_renderer.setNbPixelSamples(d.samples);
}

FigureResult renderScene(const SceneDescription& d, const RenderOptions& options) {
    FigureResult result;
    try {
        if (isRegisteredImage(d.shading)) {
            result.image = renderWithoutRays(d, result.stats);
        } else {
            SceneRender render(d, options);
            result.image = render.renderer().renderImage();
            result.stats = render.renderer().stats();
        }
        result.status = FigureResult::Status::Rendered;
    } catch (const NotDoneYet& e) {
        result.status = FigureResult::Status::NotDoneYet;
        result.message = e.what();
        result.todo = e;
    } catch (const std::exception& e) {
        result.status = FigureResult::Status::Failed;
        result.message = e.what();
    }
    return result;
}

} // namespace raylab
