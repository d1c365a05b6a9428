#include "raylab/sampler.h"

#include "src/low_discrepancy.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>

namespace raylab {

std::string_view samplerName(SamplerKind kind) {
    switch (kind) {
    case SamplerKind::Center: return "center";
    case SamplerKind::Random: return "random";
    case SamplerKind::Stratified: return "stratified";
    case SamplerKind::Grid: return "grid";
    case SamplerKind::Sobol: return "sobol";
    case SamplerKind::R2: return "r2";
    case SamplerKind::Adaptive: return "adaptive";
    }
    return "?";
}

std::optional<SamplerKind> samplerKindFromString(std::string_view name) {
    for (SamplerKind kind : kAllSamplerKinds)
        if (samplerName(kind) == name) return kind;
    return std::nullopt;
}

std::string_view samplerNames() { return "center, random, stratified, grid, sobol, r2, adaptive"; }

namespace lowdiscrepancy {

namespace {

std::uint32_t reverseBits(std::uint32_t x) {
    x = (x << 16) | (x >> 16);
    x = ((x & 0x00ff00ffu) << 8) | ((x & 0xff00ff00u) >> 8);
    x = ((x & 0x0f0f0f0fu) << 4) | ((x & 0xf0f0f0f0u) >> 4);
    x = ((x & 0x33333333u) << 2) | ((x & 0xccccccccu) >> 2);
    return ((x & 0x55555555u) << 1) | ((x & 0xaaaaaaaau) >> 1);
}

} // namespace

std::uint32_t sobol(std::uint32_t index, int dimension) {
    // Dimension 0 is van der Corput in base 2: the index's bits mirrored behind the binary point.
    if (dimension == 0) return reverseBits(index);
    // Dimension 1 (primitive polynomial x + 1): direction numbers v_k = v_{k-1} ^ (v_{k-1} >> 1).
    std::uint32_t x = 0;
    for (std::uint32_t v = 0x80000000u; index != 0; index >>= 1, v ^= v >> 1)
        if (index & 1u) x ^= v;
    return x;
}

// owenScramble of the fraction whose bits, reversed, are `reversed`.
std::uint32_t owenScrambleReversed(std::uint32_t reversed, std::uint32_t seed) {
    std::uint32_t x = reversed + seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return reverseBits(x);
}

std::uint32_t owenScramble(std::uint32_t x, std::uint32_t seed) {
    // Owen scrambling flips each bit by a hash of the bits above it. Reversed, "the bits above"
    // become the lower bits, which is what a multiply-xorshift hash mixes upwards.
    return owenScrambleReversed(reverseBits(x), seed);
}

glm::dvec2 r2(std::uint32_t index) {
    // g is the real root of x^3 = x + 1; 1/g and 1/g^2 are badly approximable, so the points of
    // n * alpha modulo 1 fill the square evenly for every n, not only powers of two.
    constexpr double g = 1.32471795724474602596;
    const double x = double(index) / g, y = double(index) / (g * g);
    return {x - std::floor(x), y - std::floor(y)}; // the fractional parts, without the slow fmod
}

} // namespace lowdiscrepancy

namespace {

// Sobol' dimension 1 from one index to the next: k - 1 -> k clears bits 0 ... c - 1 of the index
// and sets bit c (c = the trailing zeros of k), so the point changes by v_0 ^ ... ^ v_c; here
// that change with its bits reversed, as owenScrambleReversed takes it.
constexpr std::array<std::uint32_t, 32> sobol1ReversedSteps() {
    std::array<std::uint32_t, 32> steps{};
    std::uint32_t v = 0x80000000u, sum = 0;
    for (int c = 0; c < 32; ++c, v ^= v >> 1) {
        sum ^= v;
        std::uint32_t reversed = 0;
        for (int bit = 0; bit < 32; ++bit)
            if (sum & (1u << bit)) reversed |= 1u << (31 - bit);
        steps[std::size_t(c)] = reversed;
    }
    return steps;
}
constexpr std::array<std::uint32_t, 32> kSobol1ReversedSteps = sobol1ReversedSteps();

// A grid of about n cells, as square as n allows: the largest divisor of n not above sqrt(n) rows.
void gridFor(int n, int& columns, int& rows) {
    rows = int(std::sqrt(double(n)));
    while (rows > 1 && n % rows != 0) --rows;
    columns = n / rows;
}

// The largest float below 1: (k + r) / n and sums modulo 1 can round up to exactly 1 in float.
constexpr float kBelowOne = 0x1.fffffep-1f;

float toUnitFloat(std::uint32_t fraction) { return float(fraction >> 8) * 0x1p-24f; }

} // namespace

PixelSampler::PixelSampler(SamplerKind kind, int nbSamples, std::uint64_t seed, int i, int j, int width) {
    detail::SamplerState& s = m_state;
    s.kind = kind == SamplerKind::Adaptive ? SamplerKind::Stratified : kind; // adaptive's pixels are sampled as stratified
    s.nbSamples = nbSamples < 1 ? 1 : nbSamples;
    s.seed = seed;
    s.stream = std::uint64_t(j) * std::uint64_t(width) + std::uint64_t(i);
    if (s.kind == SamplerKind::Stratified || s.kind == SamplerKind::Grid)
        gridFor(s.nbSamples, s.gridWidth, s.gridHeight); // a square root and divisions: only where used
    else if (s.kind == SamplerKind::Random)
        s.rng.emplace(s.seed, s.stream); // so that next2D need not test for it at every sample
    else if (s.kind == SamplerKind::Sobol) {
        s.rng.emplace(s.seed, s.stream);
        s.scramble[0] = s.rng->nextUInt();
        s.scramble[1] = s.rng->nextUInt();
        s.drawn += 2;
    } else if (s.kind == SamplerKind::R2) {
        s.rng.emplace(s.seed, s.stream);
        s.shift[0] = double(s.rng->nextUInt()) * 0x1p-32;
        s.shift[1] = double(s.rng->nextUInt()) * 0x1p-32;
        s.drawn += 2;
    }
}

float PixelSampler::uniform() {
    detail::SamplerState& s = m_state;
    if (!s.rng) s.rng.emplace(s.seed, s.stream);
    ++s.drawn;
    return s.rng->nextFloat();
}

glm::vec2 PixelSampler::next2DOther() {
    detail::SamplerState& s = m_state;
    switch (s.kind) {
    case SamplerKind::Center: return {0.5f, 0.5f};
    case SamplerKind::Random: break; // next2D draws it
    case SamplerKind::Stratified:
    case SamplerKind::Grid: {
        const float jx = s.kind == SamplerKind::Grid ? 0.5f : uniform();
        const float jy = s.kind == SamplerKind::Grid ? 0.5f : uniform();
        const float x = (float(s.cellX) + jx) / float(s.gridWidth);
        const float y = (float(s.cellY) + jy) / float(s.gridHeight);
        // The next cell, row by row, without an integer division per sample.
        if (++s.cellX == s.gridWidth) {
            s.cellX = 0;
            if (++s.cellY == s.gridHeight) s.cellY = 0;
        }
        return {std::min(x, kBelowOne), std::min(y, kBelowOne)};
    }
    case SamplerKind::Sobol: {
        // The points of lowdiscrepancy::sobol and owenScramble, one index after the other: the
        // first dimension reversed is the index itself, the second changes by a step of the table.
        const std::uint32_t k = s.index++;
        if (k != 0) s.sobol1Reversed ^= kSobol1ReversedSteps[std::size_t(std::countr_zero(k))];
        return {toUnitFloat(lowdiscrepancy::owenScrambleReversed(k, s.scramble[0])),
                toUnitFloat(lowdiscrepancy::owenScrambleReversed(s.sobol1Reversed, s.scramble[1]))};
    }
    case SamplerKind::R2: {
        const glm::dvec2 p = lowdiscrepancy::r2(s.index++);
        double x = p.x + s.shift[0], y = p.y + s.shift[1];
        x -= x >= 1. ? 1. : 0.;
        y -= y >= 1. ? 1. : 0.;
        return {std::min(float(x), kBelowOne), std::min(float(y), kBelowOne)};
    }
    case SamplerKind::Adaptive: break; // mapped to Stratified in the constructor
    }
    return {0.5f, 0.5f};
}

} // namespace raylab
