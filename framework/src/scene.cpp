#include "raylab/scene.h"

#include "raylab/integrator.h"
#include "raylab/text.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace raylab {

SphereGeometry::SphereGeometry(const glm::vec3& center, float radius, const Color& color)
    : m_center(center), m_radius(radius), m_color(color) {
    if (!(radius > 0.f) || !std::isfinite(radius))
        throw std::invalid_argument("sphere: radius = " + showNumber(radius) +
                                    " has no meaning; it must be positive and finite");
    // The intersection needs r^2 (and |o - c|^2 of the same size): past 1.8e19 it overflows float.
    if (!std::isfinite(radius * radius))
        throw std::invalid_argument("sphere: radius = " + showNumber(radius) + " is too large: its square overflows float");
    if (!std::isfinite(center.x) || !std::isfinite(center.y) || !std::isfinite(center.z))
        throw std::invalid_argument("sphere: center = " + showVector(center) + " is not finite");
}

glm::vec3 renderOrigin(const glm::vec3& cameraPosition) {
    // x / 1024 and the product back are exact (powers of two), and so is the rounding.
    auto cell = [](float x) { return std::round(x / kRenderCell) * kRenderCell; };
    return {cell(cameraPosition.x), cell(cameraPosition.y), cell(cameraPosition.z)};
}

glm::vec3 relativeTo(const glm::vec3& point, const glm::vec3& origin) {
    return glm::vec3(glm::dvec3(point) - glm::dvec3(origin));
}

Scene relativeTo(const Scene& scene, const glm::vec3& origin) {
    Scene moved = scene;
    moved.spheres.clear();
    for (const SphereGeometry& s : scene.spheres) moved.spheres.emplace_back(relativeTo(s.center(), origin), s.radius(), s.color());
    return moved;
}

Scene makeTp1Scene() {
    Scene scene;
    scene.spheres.emplace_back(glm::vec3(0.f, 0.f, 3.f), 1.f, Color(0.f, 0.f, 1.f));
    scene.background = Color(0.5f, 0.5f, 0.5f);
    return scene;
}

Color DirectionIntegrator::Li(const Scene& /*scene*/, const Ray& ray) const { return (ray.direction + 1.f) * 0.5f; }

} // namespace raylab
