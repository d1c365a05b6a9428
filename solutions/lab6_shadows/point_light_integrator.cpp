// Lab 6: shadows. The reference solution; students write labs/lab6_shadows/point_light_integrator.cpp.
#include "point_light_integrator.h"

#include <glm/geometric.hpp>

#include <numbers>

namespace raylab {

// Ambient light, plus Lambert's reflection of each light the hit point sees.
Color PointLightIntegrator::Li(const Scene& scene, const Ray& ray) const {
    HitRecord hit;
    if (!scene.intersect(ray, hit)) return scene.background;
    const Color& colour = hit.object->color();
    glm::vec3 n = hit.object->computeNormal(hit.position);
    if (glm::dot(n, ray.direction) > 0.f) n = -n; // the side the ray sees
    Color radiance = m_ambient * colour;
    for (const PointLight& light : scene.lights) {
        const glm::vec3 toLight = light.position - hit.position;
        const float distance = glm::length(toLight);
        const float cosine = glm::dot(n, toLight) / distance;
        if (!(cosine > 0.f)) continue; // behind the surface: no shadow ray to pay for
        if (m_shadows && inShadow(scene, hit.position, light)) continue;
        radiance += colour * std::numbers::inv_pi_v<float> * light.intensity * (cosine / (distance * distance));
    }
    return radiance;
}

} // namespace raylab
