#include "commands.h"

#include "build_info.h"
#include "raylab/figure.h"

#include <algorithm>
#include <memory>
#include <cstdio>
#include <thread>
#include <vector>

namespace raylab::cli {

namespace {

// Primary rays per second on lab 5's scene: the median of `repeats` renders for each sample count,
// on one thread and on all of them.
int runBench(const std::filesystem::path& scenes, int threads, int repeats) {
    SceneDescription d = loadSceneFile(scenes / "lab5_antialiased.toml");
    const int allThreads = threads > 0 ? threads : int(std::max(1u, std::thread::hardware_concurrency()));
    std::printf("raylab bench: %s, %d x %d, %s sampler, median of %d renders\n", d.id.c_str(), d.width, d.height,
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
    std::printf("  %8s %8s %12s %16s\n", "samples", "threads", "seconds", "Mrays/s");
    for (int samples : {1, 4, 16, 64}) {
        for (int t : {1, allThreads}) {
            d.samples = samples;
            std::vector<double> seconds;
            for (int k = 0; k < repeats; ++k) {
                const FigureResult r = renderScene(d, RenderOptions{t, false});
                if (r.status != FigureResult::Status::Rendered) {
                    std::printf("%s\n", r.message.c_str());
                    return 1;
                }
                seconds.push_back(r.stats.seconds);
            }
            std::sort(seconds.begin(), seconds.end());
            const double median = seconds[seconds.size() / 2];
            const double rays = double(d.width) * d.height * samples;
            std::printf("  %8d %8d %12.4f %16.1f\n", samples, t, median, rays / median * 1e-6);
            if (allThreads == 1) break;
        }
    }
    return 0;
}

} // namespace

void addBenchCommand(CLI::App& app, Context& context) {
    auto repeats = std::make_shared<int>(3);
    CLI::App* bench = app.add_subcommand("bench", "primary rays per second on lab 5's scene at 1, 4, 16, 64 samples");
    context.addImplOption(bench);
    bench->add_option("--repeats", *repeats, "renders per measurement (the median is shown)")->check(CLI::Range(1, 100));
    context.addRenderOptions(bench);
    bench->callback([&context, repeats] {
        if (!context.ranInOtherImpl()) context.exitStatus = runBench(context.scenes, context.threads, *repeats);
    });
}

} // namespace raylab::cli
