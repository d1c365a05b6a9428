#include "raylab/sampler.h"

#include <cmath>

namespace raylab {

std::string_view samplerName(SamplerKind kind) {
    switch (kind) {
    case SamplerKind::Center: return "center";
    case SamplerKind::Random: return "random";
    case SamplerKind::Stratified: return "stratified";
    }
    return "?";
}

std::optional<SamplerKind> samplerKindFromString(std::string_view name) {
    for (SamplerKind kind : {SamplerKind::Center, SamplerKind::Random, SamplerKind::Stratified})
        if (samplerName(kind) == name) return kind;
    return std::nullopt;
}

namespace {

// A grid of about n cells, as square as n allows: the largest divisor of n not above sqrt(n) rows.
void gridFor(int n, int& columns, int& rows) {
    rows = int(std::sqrt(double(n)));
    while (rows > 1 && n % rows != 0) --rows;
    columns = n / rows;
}

} // namespace

PixelSampler::PixelSampler(SamplerKind kind, int nbSamples, std::uint64_t seed, int i, int j, int width)
    : m_kind(kind), m_nbSamples(nbSamples < 1 ? 1 : nbSamples),
      m_rng(seed, std::uint64_t(j) * std::uint64_t(width) + std::uint64_t(i)) {
    gridFor(m_nbSamples, m_gridWidth, m_gridHeight);
}

glm::vec2 PixelSampler::next2D() {
    switch (m_kind) {
    case SamplerKind::Center: return {0.5f, 0.5f};
    case SamplerKind::Random: {
        const float x = m_rng.nextFloat();
        return {x, m_rng.nextFloat()};
    }
    case SamplerKind::Stratified: {
        const int cell = m_index++ % (m_gridWidth * m_gridHeight);
        const float x = (float(cell % m_gridWidth) + m_rng.nextFloat()) / float(m_gridWidth);
        const float y = (float(cell / m_gridWidth) + m_rng.nextFloat()) / float(m_gridHeight);
        // (k + r) / n can round up to exactly 1 in float; keep the offset inside the pixel.
        return {std::fmin(x, 0x1.fffffep-1f), std::fmin(y, 0x1.fffffep-1f)};
    }
    }
    return {0.5f, 0.5f};
}

} // namespace raylab
