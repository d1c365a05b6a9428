// Lab 6: shadows. This file is yours to edit.
#include "point_light_integrator.h"
#include "raylab/todo.h"

#include <glm/geometric.hpp>

namespace raylab {

// Whether some object hides the light from `point`. Cast the shadow ray from the point towards the
// light, l = (light.position - point) / r with r the distance to the light, and ask
// scene.occluded(ray, tMin, tMax), which tells whether an object meets the ray strictly between tMin
// and tMax. tMin: a little above 0 (the handout's 1e-4), or the surface the point lies on, rounded,
// hides its own light ("shadow acne"). tMax: the light itself, t = r; an object beyond it casts no
// shadow here.
bool inShadow(const Scene& scene, const glm::vec3& point, const PointLight& light) {
    RAYLAB_TODO("lab 6", "inShadow");
}

} // namespace raylab
