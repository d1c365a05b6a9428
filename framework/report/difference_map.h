#pragma once
// The report's difference maps, on one colour scale in LSB: dark within the grader's tolerance
// (1 LSB; for a noisy figure, the reference's noise), dark red just outside, yellow at 64 LSB or more.
// A correct noisy render is dark: its pixels differ from the reference by its noise only.

#include "grader/judge/compare.h"
#include "grader/judge/references.h"
#include "raylab/image_io.h"

namespace raylab::report {

inline constexpr int kScaleFullLsb = 64;

// `verdict`: the grader's comparison of `student` with `reference` (its per-pixel error).
Image8 differenceMap(const Image8& student, const grader::FigureReference& reference, const grader::ImageVerdict& verdict);

// The scale's legend: from within tolerance (left) to kScaleFullLsb LSB (right).
Image8 differenceScale();

} // namespace raylab::report
