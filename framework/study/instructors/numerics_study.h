#pragma once
// The measurements behind docs/numerics.md. Each runs the lab code this program was built with
// (student or reference) beside the textbook and stable formulas of sphere_formulas.h, against a
// long double reference, and returns a table. `raylab numerics` runs them all.

#include "study/table.h"

#include <cstdint>

namespace raylab::study {

struct StudyOptions {
    int rays = 200000;                  // rays per configuration
    int repeats = 11;                   // timing runs; the median is kept
    std::int64_t maxSamples = 100000000; // accumulation study: up to this many samples per pixel
};

// Hit/miss misclassification, t and normal errors for spheres far away and of every size.
Table studyFarSpheres(const StudyOptions& options);
// Nanoseconds per intersection of each formula, median of options.repeats runs.
Table studyIntersectionTimes(const StudyOptions& options);
// Normal and shading errors with the camera 10^3 ... 10^7 from the origin.
Table studyLargeCoordinates(const StudyOptions& options);
// The radius-1 sphere 10^2 ... 10^5 away, filling the image: pixel count against the analytic disc.
Table studyFarDisc();
// What a naive camera or gradient does with parameters that have no meaning, and what raylab says.
Table studyDegenerateCameras();
// Pixel centres (i + 0.5) / W in float for very wide images.
Table studyPixelCentres();
// Float, compensated and double sums of up to maxSamples samples of one pixel.
Table studyAccumulation(const StudyOptions& options);

} // namespace raylab::study
