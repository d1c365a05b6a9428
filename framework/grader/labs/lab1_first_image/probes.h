#pragma once
// Lab 1's probes, typed once for both sides (grader/protocol/probe.h): the parent calls them and reads
// their answers (checks.cpp, inspector.cpp), the agent answers them (probes.cpp).

#include "grader/protocol/probe.h"

#include <vector>

namespace raylab::grader::probes {
inline namespace lab1_first_image {

// The W x H texture fillGradient wrote, row by row, its every pixel pre-filled with -1 (one never
// written shows). A list: the parent judges whether it holds W x H pixels.
inline const protocol::Probe<std::vector<glm::dvec3>(int width, int height)> fillGradient{"fillGradient"};

} // namespace lab1_first_image
} // namespace raylab::grader::probes
