// raylab bench-effects: a scene that asks for less never renders slower than one that asks for more.
// Pairs of scenes that differ in one effect, each timed as the median of several renders.
#include "commands.h"

#include "src/figure.h"
#include "src/messages.h"

#include <algorithm>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

namespace raylab::cli {

namespace {

struct Pair {
    std::string less, more;
    std::function<void(SceneDescription&)> makeLess, makeMore;
};

// The median render times of two scenes, rendered in turn (less, more, less, more...) so that a
// machine busy with something else slows both alike; at least `repeats` each, and more for quick
// scenes until each side has rendered for half a second. False when a scene did not render.
bool medianSeconds(const SceneDescription& less, const SceneDescription& more, int threads, int repeats,
                   double& tLess, double& tMore, std::string& error) {
    std::vector<double> a, b;
    double total = 0.;
    for (int k = 0; k < 500 && (k < repeats || total < 0.5); ++k) {
        for (auto [d, times] : {std::pair{&less, &a}, std::pair{&more, &b}}) {
            const FigureResult r = renderScene(*d, RenderOptions{threads, false});
            if (r.status != FigureResult::Status::Rendered) {
                error = r.message;
                return false;
            }
            times->push_back(r.stats.seconds);
        }
        total += std::min(a.back(), b.back());
    }
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    tLess = a[a.size() / 2];
    tMore = b[b.size() / 2];
    return true;
}

void samples(SceneDescription& d, SamplerKind kind, int n) {
    d.sampler = kind;
    d.samples = n;
}

int runBenchEffects(const std::filesystem::path& scenes, int threads, int repeats) {
    const SceneDescription base = sceneWithRole(loadSceneFolder(scenes), "bench", scenes);
    const std::vector<Pair> pairs = {
        {"1 centred sample", "1 random sample", [](auto& d) { samples(d, SamplerKind::Center, 1); },
         [](auto& d) { samples(d, SamplerKind::Random, 1); }},
        {"16 grid samples", "16 random samples", [](auto& d) { samples(d, SamplerKind::Grid, 16); },
         [](auto& d) { samples(d, SamplerKind::Random, 16); }},
        {"4 stratified samples", "16 stratified samples", [](auto& d) { samples(d, SamplerKind::Stratified, 4); },
         [](auto& d) { samples(d, SamplerKind::Stratified, 16); }},
        {"adaptive 16+256", "256 stratified samples",
         [](auto& d) {
             samples(d, SamplerKind::Adaptive, 16);
             d.adaptive = AdaptiveSettings{0.1f, 256, true, SamplerKind::Stratified};
         },
         [](auto& d) { samples(d, SamplerKind::Stratified, 256); }},
        {"flat shading", "cosine shading", [](auto& d) { samples(d, SamplerKind::Center, 1), d.shading = "flat"; },
         [](auto& d) { samples(d, SamplerKind::Center, 1), d.shading = "cosine"; }},
        {"no objects", "one sphere",
         [](auto& d) { samples(d, SamplerKind::Center, 1), d.scene.spheres.clear(); },
         [](auto& d) { samples(d, SamplerKind::Center, 1); }},
        {"ray directions", "flat shading", [](auto& d) { samples(d, SamplerKind::Center, 1), d.shading = "directions"; },
         [](auto& d) { samples(d, SamplerKind::Center, 1), d.shading = "flat"; }},
    };
    std::printf("raylab bench-effects: %s, %d x %d, median of %d renders; \"less\" must not be slower (5%% noise allowed)\n",
                base.id.c_str(), base.width, base.height, repeats);
    std::printf("  %-22s %10s   %-22s %10s %7s\n", "asks for less", "seconds", "asks for more", "seconds", "ratio");
    int slower = 0;
    for (const Pair& p : pairs) {
        SceneDescription less = base, more = base;
        p.makeLess(less);
        p.makeMore(more);
        std::string error;
        double tl = 0., tm = 0.;
        if (!medianSeconds(less, more, threads, repeats, tl, tm, error)) {
            std::printf("  %s\n", error.c_str());
            return 1;
        }
        const bool ok = tl <= 1.05 * tm;
        slower += !ok;
        std::printf("  %-22s %10.4f   %-22s %10.4f %7.2f  %s\n", p.less.c_str(), tl, p.more.c_str(), tm, tl / tm,
                    ok ? "ok" : "SLOWER");
    }
    std::printf("%s\n", slower == 0 ? "every scene that asks for less rendered at least as fast"
                                    : "some scenes that ask for less rendered slower (timing noise? run with more --repeats)");
    return 0; // timings are reported, never a failure: they depend on the machine
}

} // namespace

void addBenchEffectsCommand(CLI::App& app, Context& context) {
    addTimingCommand(app, context, "bench-effects", tr("cli.bench_effects"), 5, runBenchEffects);
}

} // namespace raylab::cli
