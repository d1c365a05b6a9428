// Lab 6: shadows. The reference solution; students write labs/lab6_shadows/shadow_test.cpp.
#include "point_light_integrator.h"

#include <glm/geometric.hpp>

namespace raylab {

namespace {

// Shadow rays start this far along, past the rounding of the point they leave ("shadow acne"): far
// above the error of a hit point in the course's scenes (about 1e-6), far below their sizes (about 1).
constexpr float kShadowRayStart = 1e-4f;

} // namespace

// Whether some object hides the light from `point`: the shadow ray from the point towards the light,
// from kShadowRayStart up to the light (t = r for a unit direction) and not beyond.
bool inShadow(const Scene& scene, const glm::vec3& point, const PointLight& light) {
    const glm::vec3 toLight = light.position - point;
    const float distance = glm::length(toLight);
    return scene.occluded(Ray{point, toLight / distance}, kShadowRayStart, distance);
}

} // namespace raylab
