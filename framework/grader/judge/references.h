#pragma once
// The reference outputs the grader compares against, made by `raylab references` from solutions/, so
// grading never needs solutions/: each lab's in its grading folder, framework/grader/labs/<lab>/references/.
//
//   <id>.png   the reference picture (8-bit, as the student's)
//   <id>.toml  its lab, its kind, the time the reference took to render it (render_milliseconds,
//              rounded up to 100 ms: a lab's time budget is made from it, time_budget.h) and, for a
//              deterministic figure, the pixels whose value is
//              ambiguous at float precision; for a random figure, the statistical thresholds
//   <id>.mean.png, <id>.meanfrac.png, <id>.sd.png   a random figure's converged per-pixel mean
//              (integer part, fraction x 256) and the standard deviation of one sample (x 3), in LSB

#include "raylab/image_io.h"

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace raylab::grader {

inline constexpr float kSdScale = 3.f; // sd.png stores round(3 sd), in LSB

// A random figure's converged reference: per pixel and channel, in LSB (0 ... 255).
struct StatisticalReference {
    int samples = 1;              // samples per pixel of the graded figure
    std::vector<float> mean;      // 3 a pixel: the converged mean
    std::vector<float> sampleSd;  // 3 a pixel: the standard deviation of a single sample
    double rmseLimit = 0.;        // 1.25 x the worst RMSE of correct renders over 20 seeds
    double worstCorrectRmse = 0.; // what was measured, for the report
    double biasLsb = 0.05;        // allowed mean signed difference beyond 4 standard errors
    double outlierZ = 6.;         // a pixel with |z| above this is an outlier
};

struct FigureReference {
    std::string id;
    int lab = 0;
    Image8 image;
    std::vector<std::pair<int, int>> ambiguous; // (i, j) of pixels not held to 1 LSB
    std::optional<StatisticalReference> stats;  // set for random figures
    double renderSeconds = 0.; // the reference's wall-clock time for one render (0: not recorded)
};

struct ReferenceSet {
    std::vector<FigureReference> figures; // in the order of their lab, then id

    const FigureReference* find(const std::string& id) const;
};

// Reads every <id>.toml of the folders (each lab's); throws std::runtime_error naming the file and the
// problem, or when they hold no reference at all.
ReferenceSet loadReferences(const std::vector<std::filesystem::path>& folders);

// Writes one figure's reference files into the folder; a file whose content did not change is left
// byte for byte (writePngIfChanged), so that a regeneration shows only what it changed.
void writeReference(const std::filesystem::path& folder, const FigureReference& reference);

// Writes the picture as a PNG unless the file already holds the same pixels (an encoder's other
// choices are not a change); true when it wrote.
bool writePngIfChanged(const std::filesystem::path& path, const Image8& image);

} // namespace raylab::grader
