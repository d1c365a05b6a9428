#pragma once
// How `raylab references` decides a figure's reference (docs/grading.md): rendered from the lab
// code this program was built with (solutions/), with the ambiguous pixels of a deterministic
// figure, or the converged statistics and the RMSE limit of a random one.

#include "grader/judge/references.h"

#include "src/scene_file.h"

#include <utility>
#include <vector>

namespace raylab::grader {

// What the 20 correct renders of a random figure showed besides its RMSE limit: printed, so the
// thresholds' margins are seen.
struct StatisticalMargins {
    double worstBias = 0.;     // the worst |mean signed difference| (LSB)
    double biasLimit = 0.;     // the |mean signed difference| allowed (LSB)
    double worstOutliers = 0.; // the most pixels with |z| > 6
};

struct RenderedReference {
    FigureReference reference;
    StatisticalMargins margins; // random figures only
};

// A figure whose samples are drawn at random, graded by statistics rather than pixel by pixel.
bool isStatistical(const SceneDescription& d);

// The reference of a figure of lab `lab`. Throws std::runtime_error when it does not render or has
// NaN pixels.
RenderedReference renderReference(const SceneDescription& d, int lab, int threads);

// Pixels whose centre ray is within 2e-3 pixel of a change of more than 1 LSB: a float or double
// computation of the same formula may land on either side (a centre ray grazing the silhouette).
std::vector<std::pair<int, int>> ambiguousPixels(const SceneDescription& d, int threads);

// The expected 8-bit value of an N-sample mean that is normal(m, sd^2) in LSB: rounding is not
// unbiased near a constant value (a background of 127.5 LSB is always written 128).
double expectedByte(double m, double sd);

// The converged per-pixel mean and the standard deviation of one uniform sample, in LSB.
StatisticalReference convergedStatistics(const SceneDescription& d, int threads);

} // namespace raylab::grader
