// Lab 7's functions as the crash finder calls them (src/figure_steps.h), on each pixel centre's ray:
// the triangles' intersections, then the normals where they hit.
#include "src/figure_steps.h"

#include "shapes.h"

#include <limits>

namespace raylab {

namespace {

void intersections(FigureStepContext& c) {
    for (const Triangle& triangle : c.render->scene().all<Triangle>()) {
        HitRecord hit;
        (void)triangle.intersect(c.ray, 0.f, std::numeric_limits<float>::infinity(), hit);
    }
}

// Each hit found again: the step before made these very calls and survived them.
void normals(FigureStepContext& c) {
    for (const Triangle& triangle : c.render->scene().all<Triangle>()) {
        HitRecord hit;
        if (triangle.intersect(c.ray, 0.f, std::numeric_limits<float>::infinity(), hit)) (void)triangle.computeNormal(hit.position);
    }
}

} // namespace

RAYLAB_REGISTER_FIGURE_STEP("Triangle::intersect", FigureStage::Pixel, intersections);
RAYLAB_REGISTER_FIGURE_STEP("Triangle::computeNormal", FigureStage::Pixel, normals);

} // namespace raylab
