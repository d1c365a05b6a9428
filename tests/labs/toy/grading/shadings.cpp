// The toy lab's picture, by the name its scene file's [render] shading gives: each object in its flat
// colour (the lab's own [[toy_square]] among them), elsewhere the ray's direction as toyColour draws it.
#include "raylab/integrator_registry.h"
#include "toy_colour.h"

#include <limits>

namespace raylab {
namespace {

class ToyIntegrator final : public Integrator {
public:
    Color Li(const Scene& scene, const Ray& ray) const override {
        HitRecord hit;
        if (scene.intersect(ray, 0.f, std::numeric_limits<float>::infinity(), hit)) return hit.object->color();
        return toyColour(ray);
    }
};

} // namespace

RAYLAB_REGISTER_INTEGRATOR("toy_inverted_directions", ToyIntegrator);

} // namespace raylab
