#pragma once
// Lab 3's probes, typed once for both sides (grader/protocol/probe.h): the parent calls them and reads
// their answers (checks.cpp, inspector.cpp), the agent answers them (probes.cpp).

#include "grader/protocol/probe_types.h"

namespace raylab::grader::probes {
inline namespace lab3_sphere {

inline const protocol::Probe<Hit(Sphere, Ray, double tMin, double tMax)> intersect{"intersect"};
inline const protocol::Probe<glm::dvec3(Sphere, glm::dvec3 point)> computeNormal{"computeNormal"};
// The colour RayCastIntegrator::Li gives with lab 3's shading number `shading` (answers.h), in a
// scene of one sphere of that colour.
inline const protocol::Probe<glm::dvec3(int shading, Sphere, glm::dvec3 colour, glm::dvec3 background, Ray)> li{"Li"};

} // namespace lab3_sphere
} // namespace raylab::grader::probes
