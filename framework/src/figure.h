#pragma once
// Renders a scene description with whichever lab code this program was built with.

#include "raylab/perspective_camera.h"
#include "src/render_space.h"
#include "raylab/renderer.h"
#include "raylab/integrator_registry.h"
#include "src/scene_file.h"
#include "raylab/todo.h"

#include <memory>
#include <optional>
#include <string>

namespace raylab {

struct RenderOptions {
    int threads = 0;       // 0: one per core
    bool progress = false; // a progress bar on a terminal
};

// The one place a scene description becomes what renders it: the scene moved into the camera's
// render space, the camera placed there, the integrator its picture asks for, and a renderer set
// up with its sampler, seed, adaptive settings and samples (lab 5's setter is called only when the
// scene wants more than one sample). Everything that renders a scene file builds this, so none
// can skip the render space. A gradient (lab 1) has no rays: it throws std::invalid_argument.
// Not copyable: the renderer refers to the scene, camera and integrator held here.
class SceneRender {
public:
    explicit SceneRender(const SceneDescription& description, const RenderOptions& options = {});
    SceneRender(const SceneRender&) = delete;
    SceneRender& operator=(const SceneRender&) = delete;

    const RenderSpace& space() const { return m_space; }
    const Scene& scene() const { return m_scene; } // in render space
    const PerspectiveCamera& camera() const { return m_camera; }
    const Integrator& integrator() const { return *m_integrator; }
    Renderer& renderer() { return m_renderer; }

private:
    RenderSpace m_space;
    Scene m_scene;
    PerspectiveCamera m_camera;
    std::unique_ptr<Integrator> m_integrator;
    Renderer m_renderer;
};

struct FigureResult {
    enum class Status {
        Rendered,
        NotDoneYet, // a lab stub was reached: message names the function and where to write it
        Failed,     // anything else the code threw: message says what
    };
    Status status = Status::Failed;
    std::string message;
    std::optional<NotDoneYet> todo; // NotDoneYet: the stub that was reached
    std::optional<Texture> image;
    RenderStats stats;
};

// Never throws: a stub or an error in the lab code is reported in the result.
FigureResult renderScene(const SceneDescription& description, const RenderOptions& options);

} // namespace raylab
