#pragma once
// PCG32 (O'Neill 2014): a small, fast generator with independent streams. The renderer gives every
// pixel its own stream, so an image does not depend on which thread rendered which pixel.

#include <cstdint>

namespace raylab {

class Pcg32 {
public:
    Pcg32(std::uint64_t seed, std::uint64_t stream);

    std::uint32_t nextUInt();
    // Uniform in [0, 1): the top 24 bits, so every value is exact in float and 1 is never returned.
    float nextFloat() { return float(nextUInt() >> 8) * 0x1p-24f; }

private:
    std::uint64_t m_state = 0;
    std::uint64_t m_increment;
};

} // namespace raylab
