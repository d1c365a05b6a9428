#pragma once
// The toy lab's probe as both sides know it: the parent sends its name, the agent answers it
// (probes.cpp) and the parent checks the size of the answer.
#include "grader/protocol/protocol.h"

namespace raylab::grader::probes {

// direction d -> toyColour of a ray from the origin along d
inline const protocol::ProbeSpec* const toyColour = protocol::registerProbe({"toyColour", 3, 3});

} // namespace raylab::grader::probes
