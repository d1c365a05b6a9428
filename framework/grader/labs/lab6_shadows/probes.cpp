// Lab 6's probes, in the agent: inShadow and PointLightIntegrator::Li in a scene of a sphere, a plane
// and one light.
#include "grader/protocol/agent/probes.h"
#include "probes.h"

#include "point_light_integrator.h"

namespace raylab::agent {

namespace {

namespace probes = grader::probes;

// The sphere, then the plane, each left out when its radius or its normal is zero (as floats).
Scene scene(const probes::ColouredObjects& objects) {
    Scene s;
    const float radius = float(objects.sphere.radius);
    if (radius != 0.f) s.add(SphereGeometry(glm::vec3(objects.sphere.centre), radius, Color(objects.sphereColour)));
    const glm::vec3 normal(objects.plane.normal);
    if (normal != glm::vec3(0.f)) s.add(Plane(glm::vec3(objects.plane.point), normal, Color(objects.planeColour)));
    return s;
}

bool inShadowProbe(probes::Objects objects, glm::dvec3 point, glm::dvec3 lightPosition) {
    const Scene s = scene({objects.sphere, glm::dvec3(1.), objects.plane, glm::dvec3(1.)}); // white: inShadow reads no colour
    return inShadow(s, glm::vec3(point), PointLight{glm::vec3(lightPosition)});
}

glm::dvec3 liProbe(double ambient, bool shadows, probes::ColouredObjects objects, probes::Light light, glm::dvec3 background,
                   probes::Ray r) {
    Scene s = scene(objects);
    s.lights.push_back({glm::vec3(light.position), Color(light.intensity)});
    s.background = background;
    const PointLightIntegrator integrator(float(ambient), shadows);
    return integrator.Li(s, Ray{glm::vec3(r.origin), glm::vec3(r.direction)});
}

} // namespace

RAYLAB_REGISTER_PROBE(grader::probes::inShadow, inShadowProbe);
RAYLAB_REGISTER_PROBE(grader::probes::pointLightLi, liProbe);

} // namespace raylab::agent
