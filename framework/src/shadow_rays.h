#pragma once
// How many shadow rays (Scene::occluded) this thread has traced since it started: the renderer
// takes the difference over each tile for RenderStats::shadowRays. One counter per thread, so
// counting shares nothing between threads.

#include <cstdint>

namespace raylab {

std::uint64_t shadowRaysTracedByThisThread();

} // namespace raylab
