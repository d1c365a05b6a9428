#pragma once
// Lab 6: shadows. The shadow test, and the integrator that lights each hit point by the scene's point
// lights it sees (docs/conventions.md, "Lights and planes").

#include "raylab/integrator.h"

namespace raylab {

// Lab 6: whether an object of the scene lies strictly between `point` and the light: the surface
// `point` lies on does not hide it, nor does an object beyond the light.
bool inShadow(const Scene& scene, const glm::vec3& point, const PointLight& light);

// Lab 6: Lambert's diffuse reflection of each point light,
//   L = ambient * colour + sum over the lights of colour / pi * I * max(n . l, 0) / r^2,
// a light counting only where the point is not in its shadow when `shadows` is on (a figure without
// shadows leaves the test out). A miss sees the background.
class PointLightIntegrator final : public Integrator {
public:
    PointLightIntegrator(float ambient, bool shadows) : m_ambient(ambient), m_shadows(shadows) {}
    Color Li(const Scene& scene, const Ray& ray) const override;
    bool shadows() const { return m_shadows; }

private:
    float m_ambient;
    bool m_shadows;
};

} // namespace raylab
