// Lab 3: shading the sphere. This file is yours to edit.
#include "raylab/integrator.h"
#include "raylab/todo.h"

#include <glm/geometric.hpp>

#include <algorithm>

namespace raylab {

// The colour the ray brings back. Find the nearest hit with scene.intersect(ray, hit); a ray that
// hits nothing sees scene.background. The object hit is hit.object (its colour: hit.object->color()).
// Then, by m_shading:
//   Shading::Flat               the object's colour;
//   Shading::PlaceholderNormal  colour * max(-d . n, 0) with n = normalize(1, 1, 1), turned to face
//                               the ray (n = -n when d . n > 0): the handout's intermediate picture;
//   Shading::Cosine             colour * max(-d . n, 0) with the true normal n = computeNormal(p).
// Compute the normal only when the shading needs it.
Color RayCastIntegrator::Li(const Scene& scene, const Ray& ray) const {
    RAYLAB_TODO("lab 3", "RayCastIntegrator::Li");
}

} // namespace raylab
