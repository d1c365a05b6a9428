#pragma once
// Where in a pixel the samples go. A PixelSampler serves the N sample offsets of one pixel,
// each in [0, 1)^2 from the pixel's top-left corner. Every sampler depends only on the seed and
// the pixel, never on the order pixels are rendered in, so an image is the same on any thread count.

#include "raylab/random.h"

#include <glm/vec2.hpp>

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
    Adaptive,   // a renderer strategy (renderer.h); its pixels are sampled as AdaptiveSettings::within
};

inline constexpr SamplerKind kAllSamplerKinds[] = {SamplerKind::Center, SamplerKind::Random, SamplerKind::Stratified,
                                                   SamplerKind::Grid,   SamplerKind::Sobol,  SamplerKind::R2,
                                                   SamplerKind::Adaptive};

std::string_view samplerName(SamplerKind kind);
std::optional<SamplerKind> samplerKindFromString(std::string_view name);
// "center, random, stratified, grid, sobol, r2, adaptive": for error messages and help.
std::string_view samplerNames();

class PixelSampler {
public:
    // The samples of pixel (i, j) of an image `width` pixels wide; `seed` is the scene's.
    // Adaptive is sampled as Stratified.
    PixelSampler(SamplerKind kind, int nbSamples, std::uint64_t seed, int i, int j, int width);

    // The next sample offset in the pixel. After nbSamples calls, stratified sampling starts over
    // with new jitter, grid repeats its points, and the sequences go on.
    glm::vec2 next2D() {
        if (m_kind != SamplerKind::Random) return next2DOther();
        m_drawn += 2;
        const float x = m_rng->nextFloat();
        return {x, m_rng->nextFloat()};
    }

    // How many numbers this sampler took from its random generator (0 for center and grid).
    std::uint64_t randomNumbersDrawn() const { return m_drawn; }

private:
    glm::vec2 next2DOther();
    float uniform();

    SamplerKind m_kind;
    int m_nbSamples;
    std::uint32_t m_index = 0;
    int m_gridWidth = 1;  // stratified and grid: cells per row
    int m_gridHeight = 1; // stratified and grid: cells per column
    int m_cellX = 0;  // stratified and grid: the cell of the next sample
    int m_cellY = 0;
    std::uint64_t m_seed;
    std::uint64_t m_stream;
    std::optional<Pcg32> m_rng; // random: seeded in the constructor; the others on their first draw
    std::uint64_t m_drawn = 0;
    std::uint32_t m_scramble[2] = {0, 0}; // sobol: per-pixel Owen scrambling seeds
    std::uint32_t m_sobol1Reversed = 0;   // sobol: the last point's second dimension, bits reversed
    double m_shift[2] = {0., 0.};         // r2: per-pixel offset
};

} // namespace raylab
