#pragma once
// How many shadow rays (Scene::occluded) this thread has traced since it started: the renderer
// takes the difference over each tile for RenderStats::shadowRays. One counter per thread, so
// counting shares nothing between threads.

#include <cstdint>

namespace raylab {

std::uint64_t shadowRaysTracedByThisThread();

// The grader's probe of a reference's sensitivity to rounding (grader/judge/reference_render.cpp,
// docs/grading.md, "Deterministic figures"): while `ulps` is not 0 on a thread, each shadow ray that
// thread traces leaves its point moved off the surface the point lies on (the object nearest to it),
// along that surface's normal, by `ulps` float spacings at the point's scale (max(|x|, |y|, |z|, 1));
// negative: into the surface. That is where another correct camera or intersection puts a hit point
// that the reference's rounding put elsewhere. 0 (the default): the point as given.
void setShadowOriginOffsetOnThisThread(float ulps);

} // namespace raylab
