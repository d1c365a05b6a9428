// Lab 3's probes, in the agent: intersect, computeNormal and Li on one sphere.
#include "grader/protocol/agent/probes.h"
#include "probes.h"

#include "raylab/integrator.h"
#include "raylab/sphere_geometry.h"

#include <stdexcept>
#include <string>

namespace raylab::agent {

namespace {

namespace probes = grader::probes;

SphereGeometry sphere(const probes::Sphere& s, const Color& colour = Color(1.f)) {
    return SphereGeometry(glm::vec3(s.centre), float(s.radius), colour);
}

Ray ray(const probes::Ray& r) { return Ray{glm::vec3(r.origin), glm::vec3(r.direction)}; }

probes::Hit intersectProbe(probes::Sphere s, probes::Ray r, double tMin, double tMax) {
    HitRecord hit;
    hit.t = -7.f; // a miss must leave it alone
    const bool found = sphere(s).intersect(ray(r), float(tMin), float(tMax), hit);
    return {found, hit.t, hit.position};
}

glm::dvec3 normalProbe(probes::Sphere s, glm::dvec3 point) { return sphere(s).computeNormal(glm::vec3(point)); }

glm::dvec3 liProbe(int shading, probes::Sphere s, glm::dvec3 colour, glm::dvec3 background, probes::Ray r) {
    if (shading < 0 || shading > 2) throw std::invalid_argument("probe Li: no shading " + std::to_string(shading));
    Scene scene;
    scene.add(sphere(s, Color(colour)));
    scene.background = background;
    const RayCastIntegrator integrator{Shading(shading)};
    return integrator.Li(scene, ray(r));
}

} // namespace

RAYLAB_REGISTER_PROBE(grader::probes::intersect, intersectProbe);
RAYLAB_REGISTER_PROBE(grader::probes::computeNormal, normalProbe);
RAYLAB_REGISTER_PROBE(grader::probes::li, liProbe);

} // namespace raylab::agent
