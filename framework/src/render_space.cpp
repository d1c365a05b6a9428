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
    moved.planes.clear();
    for (const Plane& p : scene.planes) moved.planes.emplace_back(toRender(p.point()), p.normal(), p.color());
    for (PointLight& light : moved.lights) light.position = toRender(light.position);
    return moved;
}

} // namespace raylab
