#include "raylab/scene.h"

namespace raylab {

Scene makeTp1Scene() {
    Scene scene;
    scene.spheres.emplace_back(glm::vec3(0.f, 0.f, 3.f), 1.f, Color(0.f, 0.f, 1.f));
    scene.background = Color(0.5f, 0.5f, 0.5f);
    return scene;
}

} // namespace raylab
