#pragma once
// Lab 2's probes as both sides know them: the parent sends their names, the agent answers them
// (probes.cpp) and the parent checks the size of the answer.
#include "grader/protocol/protocol.h"

namespace raylab::grader::probes {

// default camera (W, H, fovy) -> height, width, topLeft
inline const protocol::ProbeSpec* const viewport = protocol::registerProbe({"viewport", 3, 5});
// camera (W, H, fovy, px, py, pz) moved to p, generateRay(sx, sy) -> origin, direction
inline const protocol::ProbeSpec* const generateRay = protocol::registerProbe({"generateRay", 8, 6});

} // namespace raylab::grader::probes
