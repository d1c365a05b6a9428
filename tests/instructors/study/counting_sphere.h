#pragma once
// Lab 3's sphere, counting its calls, for the tests that check the renderer does only what a scene asks.

#include <atomic>
#include <cstdint>

namespace raylab::test {

extern std::atomic<std::uint64_t> sphereIntersections; // SphereGeometry::intersect calls
extern std::atomic<std::uint64_t> sphereNormals;       // SphereGeometry::computeNormal calls

} // namespace raylab::test
