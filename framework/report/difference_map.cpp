#include "report/difference_map.h"

#include <algorithm>
#include <cstdlib>

namespace raylab::report {

namespace {

constexpr int kScaleWidth = 256, kScaleHeight = 12, kScaleWithin = 48; // the legend's dark part, in pixels

// `lsb`: the largest channel difference; `within`: the grader's tolerance holds for this pixel.
void push(std::vector<std::uint8_t>& rgb, float lsb, bool within) {
    if (within) { // dark grey, a little lighter where the noise is larger
        const auto g = std::uint8_t(std::min(40.f, 4.f * lsb));
        rgb.insert(rgb.end(), {g, g, g});
        return;
    }
    const float x = std::clamp((lsb - 2.f) / float(kScaleFullLsb - 2), 0.f, 1.f);
    rgb.push_back(std::uint8_t(110.f + 145.f * std::min(1.f, 2.f * x)));
    rgb.push_back(std::uint8_t(x > 0.5f ? 255.f * (x - 0.5f) * 2.f : 0.f));
    rgb.push_back(0);
}

int largestChannelDifference(const std::uint8_t* a, const std::uint8_t* b) {
    return std::max({std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])});
}

} // namespace

Image8 differenceMap(const Image8& student, const grader::FigureReference& reference, const grader::ImageVerdict& verdict) {
    const Image8& r = reference.image;
    Image8 map{r.width, r.height, {}};
    map.rgb.reserve(std::size_t(r.width) * std::size_t(r.height) * 3);
    const bool sameSize = student.width == r.width && student.height == r.height;
    const bool hasError = verdict.error.size() == std::size_t(r.width) * std::size_t(r.height);
    const float limit = reference.stats ? float(reference.stats->outlierZ) : 1.f; // the verdict's unit
    for (int j = 0; j < r.height; ++j)
        for (int i = 0; i < r.width; ++i) {
            const std::size_t k = std::size_t(j) * std::size_t(r.width) + std::size_t(i);
            const float lsb = sameSize ? float(largestChannelDifference(student.pixel(i, j), r.pixel(i, j))) : float(kScaleFullLsb);
            const bool within = hasError ? verdict.error[k] <= limit : lsb <= 1.f;
            push(map.rgb, lsb, within);
        }
    return map;
}

Image8 differenceScale() {
    Image8 scale{kScaleWidth, kScaleHeight, {}};
    for (int j = 0; j < kScaleHeight; ++j)
        for (int i = 0; i < kScaleWidth; ++i) {
            const bool within = i < kScaleWithin;
            const float lsb = within ? float(i) / kScaleWithin * 10.f
                                     : 2.f + float(i - kScaleWithin) / float(kScaleWidth - 1 - kScaleWithin) * (kScaleFullLsb - 2);
            push(scale.rgb, lsb, within);
        }
    return scale;
}

} // namespace raylab::report
