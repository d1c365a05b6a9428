#pragma once
// The kinds of pixel samplers and what a PixelSampler (raylab/sampler.h) keeps between two samples:
// the framework's part of the samplers, for the renderer, the scene files and the studies. Nothing
// here is a lab's to write.

#include "raylab/random.h"

#include <cstdint>
#include <optional>
#include <string_view>

namespace raylab {

enum class SamplerKind {
    Center,     // every sample at the pixel centre (0.5, 0.5): no random numbers at all
    Random,     // independent uniform points
    Stratified, // one jittered point in each cell of a grid of about N cells
    Grid,       // the centres of the cells of that grid: no random numbers at all
    Sobol,      // the 2D Sobol' (0, 2)-sequence, Owen-scrambled per pixel (Burley 2020)
    R2,         // Roberts' R2 sequence (plastic number), shifted per pixel (Cranley-Patterson)
    Adaptive,   // a renderer strategy (detail/render_settings.h); its pixels are sampled as AdaptiveSettings::within
};

inline constexpr SamplerKind kAllSamplerKinds[] = {SamplerKind::Center, SamplerKind::Random, SamplerKind::Stratified,
                                                   SamplerKind::Grid,   SamplerKind::Sobol,  SamplerKind::R2,
                                                   SamplerKind::Adaptive};

std::string_view samplerName(SamplerKind kind);
std::optional<SamplerKind> samplerKindFromString(std::string_view name);
// "center, random, stratified, grid, sobol, r2, adaptive": for error messages and help.
std::string_view samplerNames();

namespace detail {

// A PixelSampler's state (framework/src/sampler.cpp).
struct SamplerState {
    SamplerKind kind = SamplerKind::Center;
    int nbSamples = 1;
    std::uint32_t index = 0;
    int gridWidth = 1;  // stratified and grid: cells per row
    int gridHeight = 1; // stratified and grid: cells per column
    int cellX = 0;      // stratified and grid: the cell of the next sample
    int cellY = 0;
    std::uint64_t seed = 0;
    std::uint64_t stream = 0; // the pixel's, row-major
    std::optional<Pcg32> rng; // random: seeded in the constructor; the others on their first draw
    std::uint64_t drawn = 0;
    std::uint32_t scramble[2] = {0, 0}; // sobol: per-pixel Owen scrambling seeds
    std::uint32_t sobol1Reversed = 0;   // sobol: the last point's second dimension, bits reversed
    double shift[2] = {0., 0.};         // r2: per-pixel offset
};

} // namespace detail

} // namespace raylab
