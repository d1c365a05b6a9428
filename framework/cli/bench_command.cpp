#include "commands.h"

#include "build_info.h"
#include "src/figure.h"
#include "src/messages.h"
#ifdef RAYLAB_HAVE_YARDSTICK
#include "../study/yardstick.h"
#endif

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <optional>
#include <thread>
#include <vector>

namespace raylab::cli {

namespace {

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

// Each timing lasts at least this long, the work repeated and its time per run kept: a render at 1
// sample per pixel takes about 5 ms, which one scheduler tick on a busy machine would double.
constexpr double kShortestTiming = 0.05;

// The seconds one run of `work` takes.
template <typename F> double secondsOf(F&& work) {
    const auto start = std::chrono::steady_clock::now();
    int runs = 0;
    double seconds = 0.;
    do {
        work();
        ++runs;
        seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    } while (seconds < kShortestTiming);
    return seconds / runs;
}

// The yardstick's seconds for `d`; nothing in a tree without the solutions, where it is not built.
// The reference labs draw its image bit for bit; a student's code may not, which `check` reports.
std::optional<double> yardstickSeconds(const SceneDescription& d, const std::vector<Color>& raylabImage, bool check) {
#ifdef RAYLAB_HAVE_YARDSTICK
    std::vector<Color> hand;
    const double seconds = secondsOf([&] { hand = study::renderYardstick(d); });
    if (check && hand != raylabImage)
        std::printf("  (at %d samples per pixel raylab's image is not the yardstick's: the lab code differs)\n", d.samples);
    return seconds;
#else
    (void)d, (void)raylabImage, (void)check;
    return std::nullopt;
#endif
}

// Primary rays per second on lab 5's scene, for each sample count: raylab on one thread and the
// yardstick (framework/study/yardstick.h) in turn, `repeats` times each, so that both see the same
// load; then raylab on all threads. Shows the medians and the median of the per-pair time ratios.
int runBench(const std::filesystem::path& scenes, int threads, int repeats) {
    SceneDescription d = figureWithRole(scenes, "bench");
    const int allThreads = threads > 0 ? threads : int(std::max(1u, std::thread::hardware_concurrency()));
    std::printf("raylab bench: %s, %d x %d, %s sampler, median of %d timings (each of 50 ms at least)\n", d.id.c_str(),
                d.width, d.height,
                std::string(samplerName(d.sampler)).c_str(), repeats);
    // What the numbers depend on besides the code: the build and the machine.
    std::printf("  build %s (%s), %s compiler, %u hardware threads, \"all\" = %d\n",
                build::kBuildType[0] ? build::kBuildType : "no build type", build::kImpl,
#if defined(__clang__)
                "clang",
#elif defined(__GNUC__)
                "gcc",
#else
                "other",
#endif
                std::thread::hardware_concurrency(), allThreads);
    std::printf("  %7s | %-25s | %-25s | %-18s | %s\n", "", "raylab, 1 thread", "yardstick, 1 thread", "raylab / yardstick",
                "raylab, all threads");
    std::printf("  %7s | %12s %12s | %12s %12s | %18s | %12s\n", "samples", "Mrays/s", "ns/ray", "Mrays/s", "ns/ray",
                "time ratio", "Mrays/s");
    // Untimed, once: what a process does the first time (its pages, its allocations) is not a render's cost.
    d.samples = 1;
    renderScene(d, RenderOptions{1, false});
    yardstickSeconds(d, {}, false);
    for (int samples : {1, 4, 16, 64}) {
        d.samples = samples;
        const double rays = double(d.width) * d.height * samples;
        std::vector<double> raylab, yardstick, ratio, all;
        for (int k = 0; k < repeats; ++k) {
            FigureResult r;
            raylab.push_back(secondsOf([&] { r = renderScene(d, RenderOptions{1, false}); }));
            if (r.status != FigureResult::Status::Rendered) {
                std::printf("%s\n", r.message.c_str());
                return 1;
            }
            if (const std::optional<double> y = yardstickSeconds(d, r.image->pixels(), k == 0)) {
                yardstick.push_back(*y);
                ratio.push_back(raylab.back() / *y);
            }
            if (allThreads > 1) all.push_back(secondsOf([&] { renderScene(d, RenderOptions{allThreads, false}); }));
        }
        const double r1 = median(raylab);
        std::printf("  %7d | %12.1f %12.2f |", samples, rays / r1 * 1e-6, r1 / rays * 1e9);
        if (yardstick.empty()) std::printf(" %25s | %18s |", "(needs solutions/)", "");
        else {
            const double y1 = median(yardstick);
            std::printf(" %12.1f %12.2f | %18.3f |", rays / y1 * 1e-6, y1 / rays * 1e9, median(ratio));
        }
        if (allThreads > 1) std::printf(" %12.1f\n", rays / median(all) * 1e-6);
        else std::printf(" %12s\n", "(1 thread)");
    }
    return 0;
}

} // namespace

void addBenchCommand(CLI::App& app, Context& context) {
    addTimingCommand(app, context, "bench", tr("cli.bench"), 3, runBench);
}

} // namespace raylab::cli
