#pragma once
// The framework's own types as the labs' probes send them, in double (grader/protocol/probe.h): a ray,
// a sphere and what an intersection gives (raylab/ray.h, sphere_geometry.h, hit_record.h). Several
// labs' probes take or give them; a lab's own types stay in its probes.h.

#include "grader/protocol/probe.h"

namespace raylab::grader::probes {

struct Ray {
    glm::dvec3 origin{0.}, direction{0.};
    glm::dvec3 at(double t) const { return origin + t * direction; }
    static constexpr auto fields = std::tuple{&Ray::origin, &Ray::direction};
};
struct Sphere {
    glm::dvec3 centre{0.};
    double radius = 0.;
    static constexpr auto fields = std::tuple{&Sphere::centre, &Sphere::radius};
};
// What an intersect gives: whether it hit, and the hit record's t and position (t untouched by a
// miss: the agent sets it to -7 first).
struct Hit {
    bool found = false;
    double t = 0.;
    glm::dvec3 position{0.};
    static constexpr auto fields = std::tuple{&Hit::found, &Hit::t, &Hit::position};
};

} // namespace raylab::grader::probes
