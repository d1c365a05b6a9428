#pragma once
// The building blocks of the Sobol' and R2 samplers (sampler.h), out of the students' header: the
// sampler and its tests use them.

#include <glm/vec2.hpp>

#include <cstdint>

namespace raylab::lowdiscrepancy {

// The first two dimensions of the Sobol' sequence, as 32-bit fixed-point fractions.
std::uint32_t sobol(std::uint32_t index, int dimension);
// Nested uniform (Owen) scrambling of a 32-bit fraction with a hash (Burley 2020, after Laine and Karras).
std::uint32_t owenScramble(std::uint32_t x, std::uint32_t seed);
// The same, of the fraction whose bits reversed are `reversed` (the sampler keeps them so).
std::uint32_t owenScrambleReversed(std::uint32_t reversed, std::uint32_t seed);
// The n-th point of R2: frac(n / g), frac(n / g^2), g the plastic number.
glm::dvec2 r2(std::uint32_t index);

} // namespace raylab::lowdiscrepancy
