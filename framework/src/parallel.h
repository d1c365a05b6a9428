#pragma once
// The one thread pool of raylab: the renderer's tiles and the grader's reference statistics run
// through it.

#include <cstddef>
#include <functional>

namespace raylab {

// The threads parallelFor runs for `items` items when asked for `threadsWanted` (0: one per core):
// never more than there are items, at least one.
unsigned workerCount(int threadsWanted, std::size_t items);

// Runs work(item, worker) for every item in [0, items), handed out in order to workerCount(...)
// threads; `worker` (0 ... workerCount - 1) lets each thread keep state of its own. With
// `progress`, a bar on standard error (terminal.h) while the calling thread waits. After an
// exception no new item starts, and the first one is rethrown once every thread has stopped.
void parallelFor(std::size_t items, int threadsWanted, bool progress,
                 const std::function<void(std::size_t item, unsigned worker)>& work);

} // namespace raylab
