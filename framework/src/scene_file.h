#pragma once
// Scene files: a TOML file says what to render and which effects it needs (scenes/README.md).

#include "raylab/integrator_registry.h"
#include "raylab/renderer.h"
#include "raylab/sampler.h"
#include "raylab/scene.h"

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace raylab {

struct CameraDescription {
    bool lookAt = false; // false: the default camera (origin, looking along +z, up +y)
    glm::vec3 position{0.f, 0.f, 0.f};
    glm::vec3 target{0.f, 0.f, 1.f};
    glm::vec3 up{0.f, 1.f, 0.f};
    float fovy = 60.f;
};

struct SceneDescription {
    std::filesystem::path file;
    std::string id; // the file name without .toml: the figure id (its lab is the lab.toml that lists it)
    std::string title;
    // [figure] roles: what a tool finds it by, not its id: "bench" (raylab bench, bench-effects and the
    // antialiasing study time it), "aliased" and "antialiased" (the report's antialiasing comparison).
    std::vector<std::string> roles;
    int width = 600;
    int height = 400;
    CameraDescription camera;
    Scene scene;
    // What the pixels show: an integrator or a picture without rays, registered by name by a lab
    // (raylab/integrator_registry.h; "gradient", "directions", "flat", "placeholder_normal", "cosine"
    // by labs 1 to 3, each in its folder framework/grader/labs/<lab>/shadings.cpp).
    std::string shading = "cosine";
    // [shading]: the values the file sets for the shading's parameters (integrator_registry.h); the
    // others keep their defaults.
    ShadingParameters shadingParameters;
    int samples = 1;
    SamplerKind sampler = SamplerKind::Center;
    std::uint64_t seed = 0;
    AdaptiveSettings adaptive; // [render.adaptive]: used when sampler is adaptive
};

// A scene file that cannot be used: what() is "FILE:LINE: [section] key: problem".
class SceneError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

SceneDescription loadSceneFile(const std::filesystem::path& file);

// What `raylab scene-format` prints: each registered kind of object's or light's table and its keys, with their
// types, ranges, defaults and meanings.
std::string sceneTablesReference();

// Every *.toml of a folder, in the order of their id.
std::vector<SceneDescription> loadSceneFolder(const std::filesystem::path& folder);

// The one scene of `scenes` (the files of `folder`) with that role; throws SceneError when none has
// it, or two.
const SceneDescription& sceneWithRole(const std::vector<SceneDescription>& scenes, std::string_view role,
                                      const std::filesystem::path& folder);

} // namespace raylab
