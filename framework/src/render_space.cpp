#include "src/render_space.h"

#include <cmath>

namespace raylab {

namespace {

// x / 1024 and the product back are exact (powers of two), and so is the rounding.
float nearestCell(float x) { return std::round(x / kRenderCell) * kRenderCell; }

} // namespace

RenderSpace::RenderSpace(const glm::vec3& cameraPosition)
    : m_origin(nearestCell(cameraPosition.x), nearestCell(cameraPosition.y), nearestCell(cameraPosition.z)) {}

glm::vec3 RenderSpace::toRender(const glm::vec3& point) const { return glm::vec3(glm::dvec3(point) - glm::dvec3(m_origin)); }

Scene RenderSpace::toRender(const Scene& scene) const {
    Scene moved = scene;
    moved.spheres.clear();
    for (const SphereGeometry& s : scene.spheres) moved.spheres.emplace_back(toRender(s.center()), s.radius(), s.color());
    return moved;
}

} // namespace raylab
