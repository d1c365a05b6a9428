#pragma once
// Lab 5's probes, typed once for both sides (grader/protocol/probe.h): the parent calls them and reads
// their answers (checks.cpp, inspector.cpp), the agent answers them (probes.cpp).

#include "grader/protocol/probe.h"

#include <vector>

namespace raylab::grader::probes {
inline namespace lab5_antialiasing {

// What setNbPixelSamples(n) did: whether it threw std::invalid_argument, and nbPixelSamples() after.
struct SampleCount {
    bool refused = false;
    int stored = 0;
    static constexpr auto fields = std::tuple{&SampleCount::refused, &SampleCount::stored};
};
// A point of the screen the camera was asked for, (sx, sy).
struct ScreenPoint {
    double x = 0., y = 0.;
    static constexpr auto fields = std::tuple{&ScreenPoint::x, &ScreenPoint::y};
};
// What renderPixel gives, with a camera that records its screen points and an integrator whose colour
// is the point (sx, sy, 1): the colour, and every point asked for, in order (one a ray traced).
struct Rendered {
    glm::dvec3 colour{0.};
    std::vector<ScreenPoint> points;
    static constexpr auto fields = std::tuple{&Rendered::colour, &Rendered::points};
};

inline const protocol::Probe<SampleCount(int samples)> setSamples{"setNbPixelSamples"};
// Pixel (i, j) of a W x H image, with n samples from a Random sampler of that seed.
inline const protocol::Probe<Rendered(int width, int height, int i, int j, int samples, double seed)> renderPixel{
    "renderPixel"};

} // namespace lab5_antialiasing
} // namespace raylab::grader::probes
