#include "raylab/random.h"

namespace raylab {

Pcg32::Pcg32(std::uint64_t seed, std::uint64_t stream) : m_increment((stream << 1u) | 1u) {
    // The reference seeding procedure: step, add the seed, step.
    nextUInt();
    m_state += seed;
    nextUInt();
}

std::uint32_t Pcg32::nextUInt() {
    const std::uint64_t old = m_state;
    m_state = old * 6364136223846793005ull + m_increment;
    const auto xorshifted = std::uint32_t(((old >> 18u) ^ old) >> 27u);
    const auto rot = std::uint32_t(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
}

} // namespace raylab
