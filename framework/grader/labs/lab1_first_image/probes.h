#pragma once
// Lab 1's probes as both sides know them: the parent sends their names, the agent answers them
// (probes.cpp) and the parent checks the size of the answer.
#include "grader/protocol/protocol.h"

namespace raylab::grader::probes {

// 3 W H values: the W x H texture a call gets.
inline bool validGradient(std::span<const double> inputs, std::span<const double> outputs) {
    return inputs[0] * inputs[1] <= protocol::kMaxPixels && double(outputs.size()) == 3. * inputs[0] * inputs[1];
}

// (W, H) -> the W x H texture fillGradient wrote (pre-filled with -1), 3 W H values
inline const protocol::ProbeSpec* const fillGradient = protocol::registerProbe({"fillGradient", 2, 0, &validGradient});

} // namespace raylab::grader::probes
