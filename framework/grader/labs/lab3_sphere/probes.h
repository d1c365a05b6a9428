#pragma once
// Lab 3's probes as both sides know them: the parent sends their names, the agent answers them
// (probes.cpp) and the parent checks the size of the answer.
#include "grader/protocol/protocol.h"

namespace raylab::grader::probes {

// sphere (c, r), ray (o, d), tMin, tMax -> hit, t, position (t untouched: -7)
inline const protocol::ProbeSpec* const intersect = protocol::registerProbe({"intersect", 12, 5});
// sphere (c, r), point -> normal
inline const protocol::ProbeSpec* const computeNormal = protocol::registerProbe({"computeNormal", 7, 3});
// shading, sphere (c, r, colour), background, ray (o, d) -> colour
inline const protocol::ProbeSpec* const li = protocol::registerProbe({"Li", 17, 3});

} // namespace raylab::grader::probes
