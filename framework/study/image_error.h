#pragma once
// How far a rendered picture is from the exact one, and what a series of such errors says.

#include "exact_disc.h"

#include <optional>
#include <vector>

namespace raylab::study {

struct ImageError {
    double rmse = 0.;           // over every pixel and channel
    double silhouetteRmse = 0.; // over the pixels the silhouette crosses (0 < coverage < 1)
    double psnr = 0.;           // 10 log10(1 / MSE), peak 1
    double maxError = 0.;       // the largest channel error
};

ImageError compare(const Texture& image, const ExactImage& exact);

// The least-squares slope of log y against log x.
double logLogSlope(const std::vector<double>& x, const std::vector<double>& y);

// Where the piecewise log-log line through (x, y) (x increasing, y mostly decreasing) first
// falls to `target`; nothing when it never does.
std::optional<double> whereReaches(const std::vector<double>& x, const std::vector<double>& y, double target);

} // namespace raylab::study
