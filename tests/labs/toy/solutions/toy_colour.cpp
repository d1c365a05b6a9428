// Lab @N@ (a toy): each primary ray coloured by its direction, inverted. The integrator that draws
// the figure is registered here, under the name its scene file's [render] shading gives.
#include "raylab/integrator_registry.h"
#include "toy_colour.h"

namespace raylab {

Color toyColour(const Ray& ray) {
    return Color(1.f) - (ray.direction + 1.f) * 0.5f;
}

namespace {

class ToyIntegrator final : public Integrator {
public:
    Color Li(const Scene&, const Ray& ray) const override { return toyColour(ray); }
};

} // namespace

RAYLAB_REGISTER_INTEGRATOR("toy_inverted_directions", ToyIntegrator);

} // namespace raylab
