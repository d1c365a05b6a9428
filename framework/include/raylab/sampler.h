#pragma once
// Where in a pixel the samples go. A PixelSampler serves the N sample offsets of one pixel,
// each in [0, 1)^2 from the pixel's top-left corner.

#include "raylab/random.h"

#include <glm/vec2.hpp>

#include <optional>
#include <string_view>

namespace raylab {

enum class SamplerKind {
    Center,     // every sample at the pixel centre (0.5, 0.5): no random numbers at all
    Random,     // independent uniform points
    Stratified, // one jittered point in each cell of a grid of about N cells
};

std::string_view samplerName(SamplerKind kind);
std::optional<SamplerKind> samplerKindFromString(std::string_view name);

class PixelSampler {
public:
    // The samples of pixel (i, j) of an image `width` pixels wide; `seed` is the scene's.
    PixelSampler(SamplerKind kind, int nbSamples, std::uint64_t seed, int i, int j, int width);

    // The next sample offset in the pixel. After nbSamples calls, stratified sampling starts over
    // with new jitter.
    glm::vec2 next2D();

private:
    SamplerKind m_kind;
    int m_nbSamples;
    int m_index = 0;
    int m_gridWidth;  // stratified: cells per row
    int m_gridHeight; // stratified: cells per column
    Pcg32 m_rng;
};

} // namespace raylab
