// Lab 6's functions as the crash finder calls them (src/figure_steps.h), on each pixel centre's ray
// of a figure drawn by its own shading: the shadow test towards each light from the nearest hit, then
// the integrator's colour.
#include "point_light_integrator.h"
#include "src/figure_steps.h"

namespace raylab {

namespace {

// The lab's integrator, or null when another lab's shading draws the figure.
const PointLightIntegrator* pointLight(const FigureStepContext& c) {
    return dynamic_cast<const PointLightIntegrator*>(&c.render->integrator());
}

void shadowTests(FigureStepContext& c) {
    const PointLightIntegrator* integrator = pointLight(c);
    if (integrator == nullptr || !integrator->shadows()) return;
    const Scene& scene = c.render->scene();
    HitRecord hit;
    if (!scene.intersect(c.ray, hit)) return;
    for (const PointLight& light : scene.lights)
        (void)inShadow(scene, hit.position, light);
}

void colour(FigureStepContext& c) {
    if (const PointLightIntegrator* integrator = pointLight(c)) (void)integrator->Li(c.render->scene(), c.ray);
}

} // namespace

RAYLAB_REGISTER_FIGURE_STEP("inShadow", FigureStage::Pixel, shadowTests);
RAYLAB_REGISTER_FIGURE_STEP("PointLightIntegrator::Li", FigureStage::Pixel, colour);

} // namespace raylab
