// Lab 7's probes, in the agent: a triangle's intersect and computeNormal.
#include "grader/protocol/agent/probes.h"
#include "probes.h"

#include "shapes.h"

namespace raylab::agent {

namespace {

namespace probes = grader::probes;

Triangle triangle(const probes::Triangle& t) {
    return Triangle(glm::vec3(t.a), glm::vec3(t.b), glm::vec3(t.c), Color(1.f));
}

probes::Hit intersectProbe(probes::Triangle t, probes::Ray r, double tMin, double tMax) {
    HitRecord hit;
    hit.t = -7.f; // a miss must leave it alone
    const bool found = triangle(t).intersect(Ray{glm::vec3(r.origin), glm::vec3(r.direction)}, float(tMin), float(tMax), hit);
    return {found, hit.t, hit.position};
}

glm::dvec3 normalProbe(probes::Triangle t, glm::dvec3 point) { return triangle(t).computeNormal(glm::vec3(point)); }

} // namespace

RAYLAB_REGISTER_PROBE(grader::probes::triangleIntersect, intersectProbe);
RAYLAB_REGISTER_PROBE(grader::probes::triangleNormal, normalProbe);

} // namespace raylab::agent
