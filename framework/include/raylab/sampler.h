#pragma once
// Where in a pixel the samples go. A PixelSampler serves the N sample offsets of one pixel,
// each in [0, 1)^2 from the pixel's top-left corner: lab 5 asks it for them with next2D(). Every
// sampler depends only on the seed and the pixel, never on the order pixels are rendered in, so an
// image is the same on any thread count.

#include "raylab/detail/sampler_state.h" // the kinds of samplers and their state: the framework's

#include <glm/vec2.hpp>

#include <cstdint>

namespace raylab {

class PixelSampler {
public:
    // The samples of pixel (i, j) of an image `width` pixels wide; `seed` is the scene's.
    PixelSampler(SamplerKind kind, int nbSamples, std::uint64_t seed, int i, int j, int width);

    // The next sample offset in the pixel. After nbSamples calls, the pattern goes on (stratified
    // sampling with new jitter, the sequences with their next points).
    glm::vec2 next2D() {
        if (m_state.kind != SamplerKind::Random) return next2DOther();
        m_state.drawn += 2;
        const float x = m_state.rng->nextFloat();
        return {x, m_state.rng->nextFloat()};
    }

    // How many numbers this sampler took from its random generator (0 for center and grid).
    std::uint64_t randomNumbersDrawn() const { return m_state.drawn; }

private:
    glm::vec2 next2DOther();
    float uniform();

    detail::SamplerState m_state;
};

} // namespace raylab
