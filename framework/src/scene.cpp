#include "raylab/scene.h"

#include "src/shadow_rays.h"

#include <cmath>

namespace raylab {

namespace {

thread_local std::uint64_t tShadowRays = 0;

} // namespace

std::uint64_t shadowRaysTracedByThisThread() { return tShadowRays; }

bool Scene::occluded(const Ray& ray, float tMin, float tMax) const {
    ++tShadowRays;
    // The open interval (tMin, tMax) of floats is the closed one between their neighbours, the
    // interval the shapes test.
    const float lo = std::nextafter(tMin, std::numeric_limits<float>::infinity());
    const float hi = std::nextafter(tMax, -std::numeric_limits<float>::infinity());
    for (const SphereGeometry& sphere : spheres)
        if (sphere.hits(ray, lo, hi)) return true;
    for (const Plane& plane : planes)
        if (plane.hits(ray, lo, hi)) return true;
    return false;
}

Scene makeTp1Scene() {
    Scene scene;
    scene.spheres.emplace_back(glm::vec3(0.f, 0.f, 3.f), 1.f, Color(0.f, 0.f, 1.f));
    scene.background = Color(0.5f, 0.5f, 0.5f);
    return scene;
}

} // namespace raylab
