#pragma once
// The toy lab's probe, typed once for both sides (grader/protocol/probe.h): the parent calls it and
// reads its answer (checks.cpp), the agent answers it (probes.cpp).

#include "grader/protocol/probe.h"

namespace raylab::grader::probes {
inline namespace toy_lab {

// toyColour of a ray from the origin along `direction`.
inline const protocol::Probe<glm::dvec3(glm::dvec3 direction)> toyColour{"toyColour"};

} // namespace toy_lab
} // namespace raylab::grader::probes
