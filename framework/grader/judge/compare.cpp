#include "grader/judge/compare.h"

#include "src/messages.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace raylab::grader {

namespace {

bool isMagenta(const std::uint8_t* p) {
    return p[0] == kNonFiniteRgb[0] && p[1] == kNonFiniteRgb[1] && p[2] == kNonFiniteRgb[2];
}


// A size mismatch or NaN pixels decide before any metric.
bool precheck(const FigureReference& reference, const Image8& student, ImageVerdict& v) {
    v.width = student.width;
    v.height = student.height;
    if (student.width != reference.image.width || student.height != reference.image.height) {
        v.reason = tr("compare.size", {{"width", std::to_string(student.width)},
                                        {"height", std::to_string(student.height)},
                                        {"figure_width", std::to_string(reference.image.width)},
                                        {"figure_height", std::to_string(reference.image.height)}});
        return false;
    }
    const int nan = countNonFinitePixels(reference.image, student);
    v.metrics.emplace_back(tr("compare.metric.nan"), nan);
    if (nan > 0) {
        v.reason = tr("compare.nan", {{"count", std::to_string(nan)}});
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

// The ambiguous pixels it excuses are those whose colour changes under rays a rounding apart from the
// reference's (reference_render.cpp's ambiguousPixels: the centre ray moved, the shadow rays' points
// moved off their surfaces): what a correct lab upstream of the figure's, written another way, can
// change. Any other pixel is held to 1 LSB, so a mistake that changes more than those pixels fails.
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
    v.metrics.emplace_back(tr("compare.metric.over"), over);
    v.metrics.emplace_back(tr("compare.metric.largest"), maxDiff);
    v.metrics.emplace_back(tr("compare.metric.ambiguous"), skipped);
    v.metrics.emplace_back(tr("compare.metric.mean_absolute"), sumAbs / (3. * w * h));
    v.passed = over == 0;
    v.reason = v.passed ? tr("compare.exact_pass")
                        : tr("compare.exact_fail", {{"count", formatFixed(over, 0)},
                                                    {"percent", formatFixed(100. * over / (double(w) * h), 2)},
                                                    {"largest", formatFixed(maxDiff, 0)}});
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
    v.metrics.emplace_back(tr("compare.metric.bias"), bias);
    v.metrics.emplace_back(tr("compare.metric.bias_limit"), biasLimit);
    v.metrics.emplace_back(tr("compare.metric.outliers"), outliers);
    v.metrics.emplace_back(tr("compare.metric.outlier_limit"), outlierLimit);
    v.metrics.emplace_back(tr("compare.metric.rmse"), rmse);
    v.metrics.emplace_back(tr("compare.metric.rmse_limit"), s.rmseLimit);
    std::string why; // each reason the render fails, joined by "; "
    auto because = [&why](const std::string& reason) { why += (why.empty() ? "" : tr("compare.separator")) + reason; };
    const bool biased = std::abs(bias) > biasLimit;
    if (biased) because(tr("compare.biased", {{"bias", formatFixed(bias, 3, true)}, {"limit", formatFixed(biasLimit, 3)}}));
    if (outliers > outlierLimit)
        because(tr("compare.outliers", {{"count", std::to_string(outliers)}, {"limit", std::to_string(outlierLimit)}}));
    // A biased image's RMSE holds its bias: "too noisy, blurred or shifted" would name a cause it may not
    // have (a sum divided by N + 1 is neither). Its RMSE still fails it, and is in the metrics.
    if (rmse > s.rmseLimit && !biased) because(tr("compare.noisy", {{"rmse", formatFixed(rmse, 3)},
                                                                        {"samples", std::to_string(s.samples)},
                                                                        {"worst", formatFixed(s.worstCorrectRmse, 3)}}));
    v.passed = why.empty() && rmse <= s.rmseLimit;
    v.reason = v.passed ? tr("compare.statistical_pass", {{"bias", formatFixed(bias, 3, true)},
                                                          {"outliers", std::to_string(outliers)},
                                                          {"rmse", formatFixed(rmse, 3)}})
                        : why;
    return v;
}

ImageVerdict compareImage(const FigureReference& reference, const Image8& student) {
    return reference.stats ? compareStatistical(reference, student) : compareDeterministic(reference, student);
}

} // namespace raylab::grader
