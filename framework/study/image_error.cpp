#include "image_error.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace raylab::study {

ImageError compare(const Texture& image, const ExactImage& exact) {
    if (image.pixels().size() != exact.pixels.size()) throw std::invalid_argument("compare: the sizes differ");
    double sum = 0., silhouetteSum = 0.;
    std::size_t silhouette = 0;
    ImageError e;
    for (std::size_t p = 0; p < exact.pixels.size(); ++p) {
        const bool edge = exact.coverage[p] > 1e-12 && exact.coverage[p] < 1. - 1e-12;
        silhouette += edge;
        for (int c = 0; c < 3; ++c) {
            const double d = double(image.pixels()[p][c]) - exact.pixels[p][c];
            sum += d * d;
            if (edge) silhouetteSum += d * d;
            e.maxError = std::max(e.maxError, std::abs(d));
        }
    }
    const double mse = sum / (3. * double(exact.pixels.size()));
    e.rmse = std::sqrt(mse);
    e.silhouetteRmse = silhouette > 0 ? std::sqrt(silhouetteSum / (3. * double(silhouette))) : 0.;
    e.psnr = mse > 0. ? 10. * std::log10(1. / mse) : INFINITY;
    return e;
}

double logLogSlope(const std::vector<double>& x, const std::vector<double>& y) {
    const std::size_t n = std::min(x.size(), y.size());
    if (n < 2) return NAN;
    double mx = 0., my = 0.;
    for (std::size_t k = 0; k < n; ++k) {
        mx += std::log(x[k]);
        my += std::log(y[k]);
    }
    mx /= double(n);
    my /= double(n);
    double sxy = 0., sxx = 0.;
    for (std::size_t k = 0; k < n; ++k) {
        sxy += (std::log(x[k]) - mx) * (std::log(y[k]) - my);
        sxx += (std::log(x[k]) - mx) * (std::log(x[k]) - mx);
    }
    return sxy / sxx;
}

std::optional<double> whereReaches(const std::vector<double>& x, const std::vector<double>& y, double target) {
    for (std::size_t k = 0; k < x.size() && k < y.size(); ++k) {
        if (y[k] > target) continue;
        if (k == 0) return x[0];
        const double t = (std::log(target) - std::log(y[k - 1])) / (std::log(y[k]) - std::log(y[k - 1]));
        return std::exp(std::log(x[k - 1]) + t * (std::log(x[k]) - std::log(x[k - 1])));
    }
    return std::nullopt;
}

} // namespace raylab::study
