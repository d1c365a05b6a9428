// raylab bench-effects: a scene that asks for less never renders slower than one that asks for more.
// Pairs of scenes that differ in one effect, each timed as the median of several renders.
#include "commands.h"

#include "raylab/integrator_registry.h"
#include "src/figure.h"
#include "src/messages.h"

#include <algorithm>
#include <cstdio>
#include <functional>
#include <string>
#include <tuple>
#include <vector>

namespace raylab::cli {

namespace {

struct Pair {
    std::string less, more;
    std::function<void(SceneDescription&)> makeLess, makeMore;
};

// One side of a pair: its median render time, and the counts of its renders (the same in each).
struct Timing {
    double seconds = 0.;
    RenderStats stats;
};

// The median render times of two scenes, rendered in turn (less, more, less, more...) so that a
// machine busy with something else slows both alike; at least `repeats` each, and more for quick
// scenes until each side has rendered for half a second. False when a scene did not render.
bool medianSeconds(const SceneDescription& less, const SceneDescription& more, int threads, int repeats,
                   Timing& tLess, Timing& tMore, std::string& error) {
    std::vector<double> a, b;
    double total = 0.;
    for (int k = 0; k < 500 && (k < repeats || total < 0.5); ++k) {
        for (auto [d, times, timing] : {std::tuple{&less, &a, &tLess}, std::tuple{&more, &b, &tMore}}) {
            const FigureResult r = renderScene(*d, RenderOptions{threads, false});
            if (r.status != FigureResult::Status::Rendered) {
                error = r.message;
                return false;
            }
            times->push_back(r.stats.seconds);
            timing->stats = r.stats;
        }
        total += std::min(a.back(), b.back());
    }
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    tLess.seconds = a[a.size() / 2];
    tMore.seconds = b[b.size() / 2];
    return true;
}

// Millions of primary rays a second.
double megaRays(const Timing& t) { return t.seconds > 0. ? double(t.stats.primaryRays) / t.seconds * 1e-6 : 0.; }

void samples(SceneDescription& d, SamplerKind kind, int n) {
    d.sampler = kind;
    d.samples = n;
}

// The bench scene shaded with the reference Lambert shading (framework/study/instructors/lambert_shading.cpp):
// without a light it traces no shadow ray; with one, a shadow ray for each hit that faces it.
void lambert(SceneDescription& d, bool light) {
    samples(d, SamplerKind::Center, 1);
    d.shading = "lambert";
    d.scene.lights.clear();
    if (light) d.scene.lights.push_back(PointLight{glm::vec3(-2.f, 2.f, 0.f), Color(20.f)});
}

int runBenchEffects(const std::filesystem::path& scenes, int threads, int repeats) {
    const SceneDescription base = figureWithRole(scenes, "bench");
    std::vector<Pair> pairs = {
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
         [](auto& d) { samples(d, SamplerKind::Center, 1), d.scene.setAll(std::vector<SphereGeometry>{}); },
         [](auto& d) { samples(d, SamplerKind::Center, 1); }},
        {"ray directions", "flat shading", [](auto& d) { samples(d, SamplerKind::Center, 1), d.shading = "directions"; },
         [](auto& d) { samples(d, SamplerKind::Center, 1), d.shading = "flat"; }},
    };
    // Where solutions/ is: the reference shading with lights.
    if (isRegisteredIntegrator("lambert"))
        pairs.push_back({"lambert, no light", "lambert, one light", [](auto& d) { lambert(d, false); },
                         [](auto& d) { lambert(d, true); }});
    std::printf("raylab bench-effects: %s, %d x %d, median of %d renders; \"less\" must not be slower (5%% noise allowed)\n",
                base.id.c_str(), base.width, base.height, repeats);
    std::printf("  %-22s %9s %8s %11s   %-22s %9s %8s %11s %6s\n", "asks for less", "seconds", "Mrays/s", "shadow rays",
                "asks for more", "seconds", "Mrays/s", "shadow rays", "ratio");
    int slower = 0;
    for (const Pair& p : pairs) {
        SceneDescription less = base, more = base;
        p.makeLess(less);
        p.makeMore(more);
        std::string error;
        Timing tl, tm;
        if (!medianSeconds(less, more, threads, repeats, tl, tm, error)) {
            std::printf("  %s\n", error.c_str());
            return 1;
        }
        const bool ok = tl.seconds <= 1.05 * tm.seconds;
        slower += !ok;
        std::printf("  %-22s %9.4f %8.2f %11llu   %-22s %9.4f %8.2f %11llu %6.2f  %s\n", p.less.c_str(), tl.seconds,
                    megaRays(tl), static_cast<unsigned long long>(tl.stats.shadowRays), p.more.c_str(), tm.seconds,
                    megaRays(tm), static_cast<unsigned long long>(tm.stats.shadowRays), tl.seconds / tm.seconds,
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
