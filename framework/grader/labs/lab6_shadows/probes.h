#pragma once
// Lab 6's probes as both sides know them: the parent sends their names, the agent answers them
// (probes.cpp) and the parent checks the size of the answer. A scene is one sphere (c, r; none when
// r = 0) and one plane (point, normal; none when the normal is 0).

#include "grader/protocol/protocol.h"

namespace raylab::grader::probes {

// sphere (c, r), plane (point, normal), point, light position -> in shadow (1) or not (0)
inline const protocol::ProbeSpec* const inShadow = protocol::registerProbe({"inShadow", 16, 1});
// ambient, shadows (1 or 0), sphere (c, r, colour), plane (point, normal, colour),
// light (position, intensity), background, ray (o, d) -> colour
inline const protocol::ProbeSpec* const pointLightLi = protocol::registerProbe({"PointLightIntegrator::Li", 33, 3});

} // namespace raylab::grader::probes
