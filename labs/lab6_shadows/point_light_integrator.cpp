// Lab 6: shadows. This file is yours to edit.
#include "point_light_integrator.h"
#include "raylab/todo.h"

#include <glm/geometric.hpp>

#include <numbers>

namespace raylab {

// The colour the ray brings back. A ray that hits nothing sees scene.background. At a hit
// (scene.intersect(ray, hit)), with colour = hit.object->color() and n its normal
// hit.object->computeNormal(hit.position), turned to face the ray (n = -n when d . n > 0: a plane is
// seen from both sides):
//   L = m_ambient * colour  +  for each light of scene.lights that the point sees:
//                              colour / pi * light.intensity * max(n . l, 0) / r^2
// with l the unit direction from the point to the light and r its distance. The point sees the light
// when n . l > 0 and, when m_shadows is on, when it is not inShadow (shadow_test.cpp). Test the
// shadow only for a light in front of the surface: it costs a ray.
Color PointLightIntegrator::Li(const Scene& scene, const Ray& ray) const {
    RAYLAB_TODO("lab 6", "PointLightIntegrator::Li");
}

} // namespace raylab
