#pragma once
// Lab 5's probes as both sides know them: the parent sends their names, the agent answers them
// (probes.cpp) and the parent checks the size of the answer.
#include "grader/protocol/protocol.h"

#include <cmath>

namespace raylab::grader::probes {

// k rays traced, the colour, then k screen points.
inline bool validRenderPixel(std::span<const double>, std::span<const double> outputs) {
    return !outputs.empty() && outputs[0] >= 0. && outputs[0] <= protocol::kMaxRays &&
           outputs[0] == std::floor(outputs[0]) && double(outputs.size()) == 4. + 2. * outputs[0];
}

// setNbPixelSamples(n) -> refused (0 or 1), nbPixelSamples()
inline const protocol::ProbeSpec* const setSamples = protocol::registerProbe({"setNbPixelSamples", 1, 2});
// (W, H, i, j, n, seed) -> rays traced k, colour, k screen points (sx, sy)
inline const protocol::ProbeSpec* const renderPixel = protocol::registerProbe({"renderPixel", 6, 0, &validRenderPixel});

} // namespace raylab::grader::probes
