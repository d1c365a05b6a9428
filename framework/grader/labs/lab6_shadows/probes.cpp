// Lab 6's probes, in the agent: inShadow and PointLightIntegrator::Li in a scene of a sphere, a plane
// and one light.
#include "grader/protocol/agent/probes.h"
#include "probes.h"

#include "point_light_integrator.h"

namespace raylab::agent {

namespace {

// The sphere (c, r, and its colour when `coloured`), then the plane (point, normal, colour when
// `coloured`), each left out when its radius or its normal is zero.
Scene scene(ProbeInputs& in, bool coloured) {
    Scene s;
    const glm::vec3 centre = in.vec3();
    const float radius = in.real();
    const Color sphereColour = coloured ? Color(in.vec3()) : Color(1.f);
    if (radius != 0.f) s.add(SphereGeometry(centre, radius, sphereColour));
    const glm::vec3 point = in.vec3(), normal = in.vec3();
    const Color planeColour = coloured ? Color(in.vec3()) : Color(1.f);
    if (normal != glm::vec3(0.f)) s.add(Plane(point, normal, planeColour));
    return s;
}

std::vector<double> inShadowProbe(ProbeInputs in) {
    const Scene s = scene(in, false);
    const glm::vec3 point = in.vec3();
    const PointLight light{in.vec3()};
    return {inShadow(s, point, light) ? 1. : 0.};
}

std::vector<double> liProbe(ProbeInputs in) {
    const float ambient = in.real();
    const bool shadows = in.number() != 0.;
    Scene s = scene(in, true);
    const glm::vec3 position = in.vec3();
    s.lights.push_back({position, in.vec3()});
    s.background = in.vec3();
    const glm::vec3 origin = in.vec3();
    const PointLightIntegrator integrator(ambient, shadows);
    std::vector<double> out;
    appendOutputs(out, integrator.Li(s, Ray{origin, in.vec3()}));
    return out;
}

} // namespace

RAYLAB_REGISTER_PROBE(grader::probes::inShadow, inShadowProbe);
RAYLAB_REGISTER_PROBE(grader::probes::pointLightLi, liProbe);

} // namespace raylab::agent
