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
    if (!std::isfinite(center.x) || !std::isfinite(center.y) || !std::isfinite(center.z))
        throw std::invalid_argument("sphere: center is not finite");
}

Scene makeTp1Scene() {
    Scene scene;
    scene.spheres.emplace_back(glm::vec3(0.f, 0.f, 3.f), 1.f, Color(0.f, 0.f, 1.f));
    scene.background = Color(0.5f, 0.5f, 0.5f);
    return scene;
}

Color DirectionIntegrator::Li(const Scene& /*scene*/, const Ray& ray) const { return (ray.direction + 1.f) * 0.5f; }

} // namespace raylab
