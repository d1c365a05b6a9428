// Lab 7's probes, in the agent: a triangle's intersect and computeNormal.
#include "grader/protocol/agent/probes.h"
#include "probes.h"

#include "shapes.h"

namespace raylab::agent {

namespace {

Triangle triangle(ProbeInputs& in) {
    const glm::vec3 a = in.vec3(), b = in.vec3();
    return Triangle(a, b, in.vec3(), Color(1.f));
}

std::vector<double> intersectProbe(ProbeInputs in) {
    const Triangle triangleHit = triangle(in);
    const glm::vec3 origin = in.vec3();
    const Ray ray{origin, in.vec3()};
    const float tMin = in.real(), tMax = in.real();
    HitRecord hit;
    hit.t = -7.f; // a miss must leave it alone
    const bool found = triangleHit.intersect(ray, tMin, tMax, hit);
    std::vector<double> out{found ? 1. : 0., hit.t};
    appendOutputs(out, hit.position);
    return out;
}

std::vector<double> normalProbe(ProbeInputs in) {
    const Triangle t = triangle(in);
    std::vector<double> out;
    appendOutputs(out, t.computeNormal(in.vec3()));
    return out;
}

} // namespace

RAYLAB_REGISTER_PROBE(grader::probes::triangleIntersect, intersectProbe);
RAYLAB_REGISTER_PROBE(grader::probes::triangleNormal, normalProbe);

} // namespace raylab::agent
