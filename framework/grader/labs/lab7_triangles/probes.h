#pragma once
// Lab 7's probes, typed once for both sides (grader/protocol/probe.h): the parent calls them and reads
// their answers (checks.cpp, inspector.cpp), the agent answers them (probes.cpp).

#include "grader/protocol/probe_types.h"

namespace raylab::grader::probes {
inline namespace lab7_triangles {

struct Triangle {
    glm::dvec3 a{0.}, b{0.}, c{0.};
    glm::dvec3 at(double u, double v) const { return a + u * (b - a) + v * (c - a); }
    static constexpr auto fields = std::tuple{&Triangle::a, &Triangle::b, &Triangle::c};
};

inline const protocol::Probe<Hit(Triangle, Ray, double tMin, double tMax)> triangleIntersect{"triangleIntersect"};
inline const protocol::Probe<glm::dvec3(Triangle, glm::dvec3 point)> triangleNormal{"triangleNormal"};

} // namespace lab7_triangles
} // namespace raylab::grader::probes
