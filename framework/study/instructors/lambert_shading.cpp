// The framework's reference shading with point lights, `[render] shading = "lambert"`: Lambert's
// diffuse reflection of each light that the hit point sees, and an ambient term,
//   L = ambient * colour + sum over the lights seen of colour / pi * I * max(n . l, 0) / r^2
// (docs/conventions.md, "Lights"). For raylab bench-effects and the tests. It is what a lab on
// shadows asks its students to write, so it is built only where solutions/ is and
// `raylab distribute` withholds it.
#include "raylab/integrator_registry.h"

#include <glm/geometric.hpp>

#include <memory>
#include <numbers>

namespace raylab {

namespace {

// Shadow rays start this far along from the hit point, so that the surface they leave does not
// shadow itself through the rounding of the hit point ("shadow acne").
constexpr float kShadowRayStart = 1e-4f;

class LambertIntegrator final : public Integrator {
public:
    explicit LambertIntegrator(float ambient) : m_ambient(ambient) {}

    Color Li(const Scene& scene, const Ray& ray) const override {
        HitRecord hit;
        if (!scene.intersect(ray, hit)) return scene.background;
        const Color& albedo = hit.object->color();
        glm::vec3 n = hit.object->computeNormal(hit.position);
        if (glm::dot(n, ray.direction) > 0.f) n = -n; // the side the ray sees: a plane is seen from both
        Color radiance = m_ambient * albedo;
        for (const PointLight& light : scene.lights) {
            const glm::vec3 toLight = light.position - hit.position;
            const float distance = glm::length(toLight);
            const glm::vec3 l = toLight / distance;
            const float cosine = glm::dot(n, l);
            if (!(cosine > 0.f)) continue; // the light is behind the surface: no shadow ray to trace
            // Up to the light (t = distance) and not beyond: an object past the light casts no shadow.
            if (scene.occluded(Ray{hit.position, l}, kShadowRayStart, distance)) continue;
            radiance += albedo * std::numbers::inv_pi_v<float> * light.intensity * (cosine / (distance * distance));
        }
        return radiance;
    }

private:
    float m_ambient;
};

const IntegratorRegistrar kLambert("lambert", {{"ambient", 0.f, 0.f, 1.f}}, [](const ShadingParameters& p) {
    return std::unique_ptr<Integrator>(std::make_unique<LambertIntegrator>(p.at("ambient")));
});

} // namespace

} // namespace raylab
