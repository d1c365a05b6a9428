#include "raylab/scene.h"

#include "src/shadow_rays.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace raylab {

namespace {

thread_local std::uint64_t tShadowRays = 0;
thread_local float tShadowOriginOffsetUlps = 0.f;

// `p` moved by `ulps` float spacings along the normal of the object nearest to it (setShadowOriginOffsetOnThisThread).
glm::vec3 movedOffItsSurface(const Scene& scene, const glm::vec3& p, float ulps) {
    std::pair<float, const Shape*> nearest{std::numeric_limits<float>::infinity(), nullptr};
    scene.forEachGroup([&](const auto& group) {
        if (const auto candidate = group.nearestSurface(p); candidate.first < nearest.first) nearest = candidate;
    });
    if (nearest.second == nullptr) return p;
    const glm::vec3 normal = glm::normalize(nearest.second->computeNormal(p));
    if (!std::isfinite(normal.x + normal.y + normal.z)) return p; // p where the normal has no direction
    const float scale = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z), 1.f});
    const float spacing = std::nextafter(scale, std::numeric_limits<float>::infinity()) - scale;
    return p + (ulps * spacing) * normal;
}

} // namespace

std::uint64_t shadowRaysTracedByThisThread() { return tShadowRays; }

void setShadowOriginOffsetOnThisThread(float ulps) { tShadowOriginOffsetUlps = ulps; }

bool Scene::occluded(const Ray& given, float tMin, float tMax) const {
    ++tShadowRays;
    const Ray ray = tShadowOriginOffsetUlps == 0.f
                        ? given
                        : Ray{movedOffItsSurface(*this, given.origin, tShadowOriginOffsetUlps), given.direction};
    // The open interval (tMin, tMax) of floats is the closed one between their neighbours, the
    // interval the shapes test.
    const float lo = std::nextafter(tMin, std::numeric_limits<float>::infinity());
    const float hi = std::nextafter(tMax, -std::numeric_limits<float>::infinity());
    bool blocked = false;
    forEachGroup([&](const auto& group) { blocked = blocked || group.hitsAny(ray, lo, hi); });
    return blocked;
}

Scene makeTp1Scene() {
    Scene scene;
    scene.add(SphereGeometry(glm::vec3(0.f, 0.f, 3.f), 1.f, Color(0.f, 0.f, 1.f)));
    scene.background = Color(0.5f, 0.5f, 0.5f);
    return scene;
}

} // namespace raylab
