#pragma once
// Lab 7's probes as both sides know them: the parent sends their names, the agent answers them
// (probes.cpp) and the parent checks the size of the answer.
#include "grader/protocol/protocol.h"

namespace raylab::grader::probes {

// triangle (a, b, c), ray (o, d), tMin, tMax -> hit, t, position (t untouched: -7)
inline const protocol::ProbeSpec* const triangleIntersect = protocol::registerProbe({"triangleIntersect", 17, 5});
// triangle (a, b, c), point -> normal
inline const protocol::ProbeSpec* const triangleNormal = protocol::registerProbe({"triangleNormal", 12, 3});

} // namespace raylab::grader::probes
