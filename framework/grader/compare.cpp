#include "grader/compare.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace raylab::grader {

namespace {

bool isMagenta(const std::uint8_t* p) {
    return p[0] == kNonFiniteRgb[0] && p[1] == kNonFiniteRgb[1] && p[2] == kNonFiniteRgb[2];
}

std::string fmt(const char* format, double a, double b = 0., double c = 0.) {
    char text[256];
    std::snprintf(text, sizeof text, format, a, b, c);
    return text;
}

// A size mismatch or NaN pixels decide before any metric.
bool precheck(const FigureReference& reference, const Image8& student, ImageVerdict& v) {
    v.width = student.width;
    v.height = student.height;
    if (student.width != reference.image.width || student.height != reference.image.height) {
        v.reason = "the image is " + std::to_string(student.width) + " x " + std::to_string(student.height) +
                   ", the figure is " + std::to_string(reference.image.width) + " x " +
                   std::to_string(reference.image.height);
        return false;
    }
    const int nan = countNonFinitePixels(reference.image, student);
    v.metrics.emplace_back("NaN pixels", nan);
    if (nan > 0) {
        v.reason = std::to_string(nan) + " pixels are NaN or infinite (magenta): a division by zero or the sqrt of a "
                                         "negative number";
        return false;
    }
    return true;
}

} // namespace

int countNonFinitePixels(const Image8& reference, const Image8& student) {
    int count = 0;
    for (int j = 0; j < student.height; ++j)
        for (int i = 0; i < student.width; ++i)
            if (isMagenta(student.pixel(i, j)) && !isMagenta(reference.pixel(i, j))) ++count;
    return count;
}

ImageVerdict compareDeterministic(const FigureReference& reference, const Image8& student) {
    ImageVerdict v;
    if (!precheck(reference, student, v)) return v;
    const int w = student.width, h = student.height;
    std::vector<char> ambiguous(std::size_t(w) * h, 0);
    for (const auto& [i, j] : reference.ambiguous)
        if (i >= 0 && j >= 0 && i < w && j < h) ambiguous[std::size_t(j) * w + i] = 1;
    v.error.resize(std::size_t(w) * h);
    int over = 0, skipped = 0, maxDiff = 0;
    double sumAbs = 0.;
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            const std::uint8_t* a = reference.image.pixel(i, j);
            const std::uint8_t* b = student.pixel(i, j);
            int d = 0;
            for (int c = 0; c < 3; ++c) {
                d = std::max(d, std::abs(int(a[c]) - int(b[c])));
                sumAbs += std::abs(int(a[c]) - int(b[c]));
            }
            const std::size_t k = std::size_t(j) * w + i;
            v.error[k] = float(d);
            if (d <= 1) continue;
            if (ambiguous[k]) ++skipped;
            else {
                ++over;
                maxDiff = std::max(maxDiff, d);
            }
        }
    v.metrics.emplace_back("pixels off by more than 1 LSB", over);
    v.metrics.emplace_back("largest difference (LSB)", maxDiff);
    v.metrics.emplace_back("ambiguous pixels allowed to differ", skipped);
    v.metrics.emplace_back("mean absolute difference (LSB)", sumAbs / (3. * w * h));
    v.passed = over == 0;
    v.reason = v.passed ? "every pixel within 1 LSB of the reference"
                        : fmt("%.0f pixels (%.2f%%) differ from the reference by more than 1 LSB, up to %.0f LSB", over,
                              100. * over / (double(w) * h), maxDiff);
    return v;
}

ImageVerdict compareStatistical(const FigureReference& reference, const Image8& student) {
    ImageVerdict v;
    if (!precheck(reference, student, v)) return v;
    const StatisticalReference& s = *reference.stats;
    const int w = student.width, h = student.height;
    const double values = 3. * w * h;
    // Each value's variance: the N-sample mean's, the reference's own (it averaged 256 strata,
    // bounded here as a 256-sample mean) and rounding to 8 bits (1/12 LSB^2).
    double sumDiff = 0., sumSq = 0., sumVar = 0.;
    int outliers = 0;
    v.error.resize(std::size_t(w) * h);
    for (std::size_t p = 0; p < std::size_t(w) * h; ++p) {
        float worstZ = 0.f;
        for (int c = 0; c < 3; ++c) {
            const std::size_t k = 3 * p + c;
            const double sd = s.sampleSd[k];
            const double var = sd * sd / s.samples + sd * sd / 256. + 1. / 12.;
            const double d = double(student.rgb[k]) - s.mean[k];
            sumDiff += d;
            sumSq += d * d;
            sumVar += var;
            worstZ = std::max(worstZ, float(std::abs(d) / std::sqrt(var)));
        }
        v.error[p] = worstZ;
        if (worstZ > s.outlierZ) ++outliers;
    }
    const double bias = sumDiff / values;
    const double standardError = std::sqrt(sumVar) / values;
    const double biasLimit = s.biasLsb + 4. * standardError;
    const double rmse = std::sqrt(sumSq / values);
    const int outlierLimit = std::max(3, int(1e-4 * w * h));
    v.metrics.emplace_back("mean signed difference (LSB)", bias);
    v.metrics.emplace_back("allowed |mean signed difference| (LSB)", biasLimit);
    v.metrics.emplace_back("pixels with |z| > 6", outliers);
    v.metrics.emplace_back("allowed outliers", outlierLimit);
    v.metrics.emplace_back("RMSE (LSB)", rmse);
    v.metrics.emplace_back("allowed RMSE (LSB)", s.rmseLimit);
    std::string why;
    if (std::abs(bias) > biasLimit)
        why += fmt("biased: the image is on average %+.3f LSB off the converged mean (allowed %.3f); ", bias, biasLimit);
    if (outliers > outlierLimit)
        why += fmt("%.0f pixels are more than 6 standard deviations off (allowed %.0f); ", outliers, outlierLimit);
    if (rmse > s.rmseLimit)
        why += fmt("too noisy or blurred: RMSE %.3f LSB, correct %.0f-sample renders reach at most %.3f; ", rmse,
                   double(s.samples), s.worstCorrectRmse);
    v.passed = why.empty();
    v.reason = v.passed ? fmt("unbiased (%+.3f LSB), %.0f outliers, RMSE %.3f LSB: a correct render", bias, outliers, rmse)
                        : why.substr(0, why.size() - 2);
    return v;
}

ImageVerdict compareImage(const FigureReference& reference, const Image8& student) {
    return reference.stats ? compareStatistical(reference, student) : compareDeterministic(reference, student);
}

} // namespace raylab::grader
