// Lab 3's probes, in the agent: intersect, computeNormal and Li on one sphere.
#include "grader/protocol/agent/probes.h"
#include "probes.h"

#include "raylab/integrator.h"
#include "raylab/sphere_geometry.h"

#include <stdexcept>
#include <string>

namespace raylab::agent {

namespace {

SphereGeometry sphere(ProbeInputs& in, const Color& colour = Color(1.f)) {
    const glm::vec3 centre = in.vec3();
    return SphereGeometry(centre, in.real(), colour);
}

Ray ray(ProbeInputs& in) {
    const glm::vec3 origin = in.vec3();
    return Ray{origin, in.vec3()};
}

std::vector<double> intersectProbe(ProbeInputs in) {
    const SphereGeometry s = sphere(in);
    const Ray r = ray(in);
    const float tMin = in.real(), tMax = in.real();
    HitRecord hit;
    hit.t = -7.f; // a miss must leave it alone
    const bool found = s.intersect(r, tMin, tMax, hit);
    std::vector<double> out{found ? 1. : 0., hit.t};
    appendOutputs(out, hit.position);
    return out;
}

std::vector<double> normalProbe(ProbeInputs in) {
    const SphereGeometry s = sphere(in);
    std::vector<double> out;
    appendOutputs(out, s.computeNormal(in.vec3()));
    return out;
}

std::vector<double> liProbe(ProbeInputs in) {
    const int shading = in.integer();
    if (shading < 0 || shading > 2) throw std::invalid_argument("probe Li: no shading " + std::to_string(shading));
    const glm::vec3 centre = in.vec3();
    const float radius = in.real();
    const Color colour = in.vec3();
    Scene scene;
    scene.add(SphereGeometry(centre, radius, colour));
    scene.background = in.vec3();
    const RayCastIntegrator integrator{Shading(shading)};
    std::vector<double> out;
    appendOutputs(out, integrator.Li(scene, ray(in)));
    return out;
}

} // namespace

RAYLAB_REGISTER_PROBE(grader::probes::intersect, intersectProbe);
RAYLAB_REGISTER_PROBE(grader::probes::computeNormal, normalProbe);
RAYLAB_REGISTER_PROBE(grader::probes::li, liProbe);

} // namespace raylab::agent
