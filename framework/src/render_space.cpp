#include "src/render_space.h"

#include <cmath>

namespace raylab {

namespace {

// x / 1024 and the product back are exact (powers of two), and so is the rounding.
float nearestCell(float x) { return std::round(x / kRenderCell) * kRenderCell; }

} // namespace

RenderSpace::RenderSpace(const glm::vec3& cameraPosition)
    : m_origin(nearestCell(cameraPosition.x), nearestCell(cameraPosition.y), nearestCell(cameraPosition.z)) {}

glm::vec3 RenderSpace::toRender(const glm::vec3& point) const { return OriginShift{m_origin}(point); }

Scene RenderSpace::toRender(const Scene& scene) const {
    const OriginShift shift{m_origin};
    Scene moved;
    moved.background = scene.background;
    scene.forEachLightKind([&](const auto& lights) {
        for (const auto& light : lights) moved.add(light.shifted(shift));
    });
    scene.forEachGroup([&](const auto& group) {
        for (const auto& object : group.objects) moved.add(object.shifted(shift));
    });
    return moved;
}

} // namespace raylab
