// Lab 3's functions as the crash finder calls them (src/figure_steps.h), on each pixel centre's ray:
// the spheres' intersections, the normals where they hit, and the ray cast integrator's colour.
#include "src/figure_steps.h"

#include <limits>

namespace raylab {

namespace {

void intersections(FigureStepContext& c) {
    for (const SphereGeometry& sphere : c.render->scene().all<SphereGeometry>()) {
        HitRecord hit;
        (void)sphere.intersect(c.ray, 0.f, std::numeric_limits<float>::infinity(), hit);
    }
}

// Each hit found again: the step before made these very calls and survived them.
void normals(FigureStepContext& c) {
    for (const SphereGeometry& sphere : c.render->scene().all<SphereGeometry>()) {
        HitRecord hit;
        if (sphere.intersect(c.ray, 0.f, std::numeric_limits<float>::infinity(), hit))
            (void)sphere.computeNormal(hit.position);
    }
}

void colour(FigureStepContext& c) {
    const auto* integrator = dynamic_cast<const RayCastIntegrator*>(&c.render->integrator());
    if (integrator != nullptr) (void)integrator->Li(c.render->scene(), c.ray); // another lab's shading is not this one
}

} // namespace

RAYLAB_REGISTER_FIGURE_STEP("SphereGeometry::intersect", FigureStage::Pixel, intersections);
RAYLAB_REGISTER_FIGURE_STEP("SphereGeometry::computeNormal", FigureStage::Pixel, normals);
RAYLAB_REGISTER_FIGURE_STEP("RayCastIntegrator::Li", FigureStage::Pixel, colour);

} // namespace raylab
