#include "src/parallel.h"

#include "src/terminal.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace raylab {

unsigned workerCount(int threadsWanted, std::size_t items) {
    const unsigned wanted = threadsWanted > 0 ? unsigned(threadsWanted) : std::max(1u, std::thread::hardware_concurrency());
    return unsigned(std::max<std::size_t>(1, std::min<std::size_t>(wanted, items)));
}

void parallelFor(std::size_t items, int threadsWanted, bool progress,
                 const std::function<void(std::size_t item, unsigned worker)>& work) {
    std::atomic<std::size_t> nextItem{0};
    std::atomic<std::size_t> itemsDone{0};
    std::atomic<bool> failed{false};
    std::exception_ptr firstError;
    std::mutex errorMutex;

    auto worker = [&](unsigned self) {
        try {
            for (std::size_t item = nextItem++; item < items && !failed; item = nextItem++) {
                work(item, self);
                ++itemsDone;
            }
        } catch (...) {
            std::lock_guard lock(errorMutex);
            if (!failed.exchange(true)) firstError = std::current_exception();
        }
    };

    const unsigned threads = workerCount(threadsWanted, items);
    std::vector<std::thread> workers;
    for (unsigned k = 1; k < threads; ++k) workers.emplace_back(worker, k);
    if (progress) {
        // The calling thread watches; the workers do the work.
        ProgressBar bar(items);
        workers.emplace_back(worker, 0u);
        while (itemsDone < items && !failed) {
            bar.update(itemsDone);
            std::this_thread::sleep_for(std::chrono::milliseconds(100));
        }
        for (auto& w : workers) w.join();
        bar.finish();
    } else {
        worker(0);
        for (auto& w : workers) w.join();
    }
    if (firstError) std::rethrow_exception(firstError);
}

} // namespace raylab
