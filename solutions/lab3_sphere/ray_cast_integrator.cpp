// Lab 3: shading the sphere. The reference solution; students write labs/lab3_sphere/ray_cast_integrator.cpp.
#include "raylab/integrator.h"

#include <glm/geometric.hpp>

#include <algorithm>

namespace raylab {

namespace {

// Lambert's cosine law with the light at the eye: the surface is as bright as it faces the ray.
Color cosineShade(const Color& color, const glm::vec3& d, const glm::vec3& n) {
    return color * std::max(-glm::dot(d, n), 0.f);
}

} // namespace

Color RayCastIntegrator::Li(const Scene& scene, const Ray& ray) const {
    HitRecord hit;
    if (!scene.intersect(ray, hit)) return scene.background;
    const Color& color = hit.object->color();
    switch (m_shading) {
    case Shading::Flat: return color; // no normal needed
    case Shading::PlaceholderNormal: {
        glm::vec3 n = glm::normalize(glm::vec3(1.f));
        if (glm::dot(ray.direction, n) > 0.f) n = -n;
        return cosineShade(color, ray.direction, n);
    }
    case Shading::Cosine:
        hit.normal = hit.object->computeNormal(hit.position);
        return cosineShade(color, ray.direction, hit.normal);
    }
    return color;
}

} // namespace raylab
