#pragma once
// PCG32 (O'Neill 2014): a small, fast generator with independent streams. The renderer gives every
// pixel its own stream, so an image does not depend on which thread rendered which pixel.

#include <cstdint>

namespace raylab {

class Pcg32 {
public:
    Pcg32(std::uint64_t seed, std::uint64_t stream) : m_increment((stream << 1u) | 1u) {
        // The reference seeding procedure: step, add the seed, step.
        nextUInt();
        m_state += seed;
        nextUInt();
    }

    // Inline: the samplers draw two per sample, and a call costs as much as the step itself.
    std::uint32_t nextUInt() {
        const std::uint64_t old = m_state;
        m_state = old * 6364136223846793005ull + m_increment;
        const auto xorshifted = std::uint32_t(((old >> 18u) ^ old) >> 27u);
        const auto rot = std::uint32_t(old >> 59u);
        return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
    }
    // Uniform in [0, 1): the top 24 bits, so every value is exact in float and 1 is never returned.
    float nextFloat() { return float(nextUInt() >> 8) * 0x1p-24f; }

private:
    std::uint64_t m_state = 0;
    std::uint64_t m_increment;
};

} // namespace raylab
