#pragma once
// Lab 4's probes as both sides know them: the parent sends their names, the agent answers them
// (probes.cpp) and the parent checks the size of the answer.
#include "grader/protocol/protocol.h"

namespace raylab::grader::probes {

// (W, H, position, target, up, fovy) -> u, v, w, position, height, width, topLeft
inline const protocol::ProbeSpec* const lookAt = protocol::registerProbe({"lookAt", 12, 17});
// (position, target, up) -> 1 when std::invalid_argument, 0 when built
inline const protocol::ProbeSpec* const lookAtRefused = protocol::registerProbe({"lookAtRefused", 9, 1});

} // namespace raylab::grader::probes
