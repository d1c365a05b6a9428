// The toy lab's picture, by the name its scene file's [render] shading gives: each object in its flat
// colour (the lab's own [[toy_square]] among them) tinted by the lab's own lamps ([[toy_lamp]]) that
// face it, when the scene has any; elsewhere the ray's direction as toyColour draws it.
#include "raylab/integrator_registry.h"
#include "toy_colour.h"

#include <glm/geometric.hpp>

#include <limits>

namespace raylab {
namespace {

class ToyIntegrator final : public Integrator {
public:
    Color Li(const Scene& scene, const Ray& ray) const override {
        HitRecord hit;
        if (!scene.intersect(ray, 0.f, std::numeric_limits<float>::infinity(), hit)) return toyColour(ray);
        const std::vector<ToyLamp>& lamps = scene.lightsOf<ToyLamp>();
        if (lamps.empty()) return hit.object->color();
        const glm::vec3 normal = hit.object->computeNormal(hit.position);
        Color tint(0.f);
        for (const ToyLamp& lamp : lamps)
            if (glm::dot(normal, lamp.position - hit.position) > 0.f) tint += lamp.tint;
        return hit.object->color() * tint;
    }
};

} // namespace

RAYLAB_REGISTER_INTEGRATOR("toy_inverted_directions", ToyIntegrator);

} // namespace raylab
