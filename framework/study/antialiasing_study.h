#pragma once
// `raylab study antialiasing`: what each sampler's accuracy costs in time, on lab 5's scene,
// against the exact picture (exact_disc.h); and the case adaptive sampling gets wrong.

#include "image_error.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace raylab::study {

struct AntialiasingOptions {
    std::filesystem::path scene;       // lab 5's scene: one sphere on the default camera's axis
    std::filesystem::path thinObjects; // scenes/study/adaptive_thin_objects.toml
    std::filesystem::path out;         // accuracy.csv, accuracy.md and the SVG plots go here
    bool quick = false;                // a 120 x 80 image, up to 256 samples, one timing run
    int repeats = 3;                   // timing runs, the median is kept (the 1024-sample runs: one)
    int threads = 0;
    bool print = true; // a line a measurement on standard output
};

// Adaptive sampling as the study runs it: `baseSamples` stratified samples in every pixel, then 256
// in the pixels whose samples differ by more than `threshold` (with `widen`, and their neighbours).
struct AdaptiveStudySetting {
    int baseSamples = 16;
    float threshold = 0.1f;
    bool widen = true;
};
inline constexpr int kAdaptiveMaxSamples = 256;

struct StudyRow {
    std::string sampler;
    std::optional<AdaptiveStudySetting> adaptive; // adaptive rows only
    double samples = 0.;    // mean samples per pixel
    double seconds = 0.;    // median render time
    int runs = 0;
    ImageError error;
    double refinedFraction = 0.; // adaptive: the share of pixels its second pass rendered
};

struct FailureRow {
    int baseSamples = 0;
    bool widen = false;
    double inkFound = 0.; // how much of the small objects' contrast the picture shows (exact: 1)
    int objectsMissed = 0;
    int objects = 0;
    double seconds = 0.;
};

struct AntialiasingResult {
    std::vector<StudyRow> rows;
    std::vector<FailureRow> failure;
    double referenceCheck = 0.; // the largest change of a reference pixel when the quadrature nodes double
    int width = 0, height = 0, silhouettePixels = 0;
};

// An adaptive row's setting as its tables show it, "16+256 t=0.05 widen"; "" for a uniform sampler.
std::string settingName(const StudyRow& row);

// Runs the study and writes its files; throws std::runtime_error when a scene does not fit.
AntialiasingResult runAntialiasingStudy(const AntialiasingOptions& options);

// The uniform samplers the study compares, in the order of its tables.
inline const std::vector<std::string> kStudySamplers = {"random", "stratified", "grid", "sobol", "r2"};

} // namespace raylab::study
