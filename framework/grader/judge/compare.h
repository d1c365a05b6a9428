#pragma once
// Image checks: a student's picture against its reference, by the policy of docs/grading.md.

#include "grader/judge/references.h"

#include <string>
#include <utility>
#include <vector>

namespace raylab::grader {

struct ImageVerdict {
    bool passed = false;
    std::string reason;                                  // one line: why it passed or failed
    std::vector<std::pair<std::string, double>> metrics; // name, value, for the report
    int width = 0, height = 0;
    std::vector<float> error; // per pixel, the largest channel difference in LSB (or |z|): the heat map
};

// Deterministic figures: every pixel within 1 LSB except the ambiguous ones; no NaN (magenta) pixel.
ImageVerdict compareDeterministic(const FigureReference& reference, const Image8& student);

// Random figures: no bias, few outliers, RMSE within the measured limit.
ImageVerdict compareStatistical(const FigureReference& reference, const Image8& student);

// Either of the above, by the reference's kind.
ImageVerdict compareImage(const FigureReference& reference, const Image8& student);

// Pixels of `student` written as NaN (magenta) where the reference is not magenta.
int countNonFinitePixels(const Image8& reference, const Image8& student);

} // namespace raylab::grader
