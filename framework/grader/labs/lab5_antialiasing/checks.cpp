// Lab 5's function checks: the sample count and the average, with a camera that counts its rays
// (no image metric can tell 4 stratified samples from 16 random ones; counting can), on the
// handout's pixels and on pixels, counts and seeds drawn at grading time.
#include "grader/judge/checks/checks.h"
#include "probes.h"

#include "src/messages.h"

#include <cmath>
#include <set>
#include <utility>

namespace raylab::grader {

namespace {

struct Pixel {
    int width, height, i, j, samples;
    std::uint64_t seed;
    protocol::Call call() const { return probes::renderPixel(width, height, i, j, samples, double(seed)); }
    std::string name() const {
        return tr("what.lab5.pixel", {{"i", std::to_string(i)}, {"j", std::to_string(j)}, {"samples", std::to_string(samples)}});
    }
};

using probes::Rendered;

void judgePixel(Judge& judge, const Pixel& p, const Rendered& r) {
    const std::string what = p.name();
    if (!judge.expectTrue(tr("what.lab5.rays_traced", {{"pixel", what}}), r.points.size() == std::size_t(p.samples),
                          std::to_string(p.samples), std::to_string(r.points.size()), tr("hint.lab5.one_ray")))
        return;
    glm::dvec3 mean(0.);
    for (const auto& [sx, sy] : r.points)
        mean += glm::dvec3(sx, sy, 1.);
    mean /= double(p.samples);
    judge.expectNear(tr("what.lab5.colour", {{"pixel", what}}), r.colour, mean, 1e-5, tr("hint.lab5.average"));
    bool inside = true;
    for (const auto& [sx, sy] : r.points)
        inside = inside && sx >= double(p.i) / p.width && sx <= double(p.i + 1) / p.width &&
                 sy >= double(p.j) / p.height && sy <= double(p.j + 1) / p.height;
    judge.expectTrue(tr("what.lab5.screen_points", {{"pixel", what}}), inside, tr("what.lab5.inside"),
                     tr("what.lab5.outside"), tr("hint.lab5.screen_point"));
}

void addChecks(LabChecks& checks, CaseRandom& random) {
    const int drawnCount = random.integer(2, 64);
    checks.add({"sample_count",
               {probes::setSamples(9), probes::setSamples(drawnCount), probes::setSamples(0), probes::setSamples(-3)},
               [drawnCount](const auto& out, Judge& judge) {
                   for (const auto& [k, n] : {std::pair{0, 9}, std::pair{1, drawnCount}}) {
                       const probes::SampleCount count = probes::setSamples.answer(out[k]);
                       judge.expectTrue(tr("what.lab5.stored", {{"n", std::to_string(n)}}),
                                        !count.refused && count.stored == n, std::to_string(n),
                                        count.refused ? "std::invalid_argument" : show(count.stored),
                                        tr("hint.lab5.store"));
                   }
                   for (const auto& [k, n] : {std::pair{2, 0}, std::pair{3, -3}})
                       judge.expectTrue("setNbPixelSamples(" + std::to_string(n) + ")",
                                        probes::setSamples.answer(out[k]).refused, "std::invalid_argument", tr("what.lab5.no_exception"),
                                        tr("hint.lab5.refuse"));
               }});

    std::vector<Pixel> pixels{{8, 4, 3, 2, 1, 7}, {8, 4, 3, 2, 5, 7}, {8, 4, 3, 2, 16, 7}};
    const int width = random.integer(2, 64), height = random.integer(2, 64);
    pixels.push_back({width, height, random.integer(0, width - 1), random.integer(0, height - 1), random.integer(2, 32),
                      std::uint64_t(random.integer(0, 1 << 30))});
    std::vector<protocol::Call> calls;
    for (const Pixel& p : pixels)
        calls.push_back(p.call());
    checks.add({"average", calls, [pixels](const auto& out, Judge& judge) {
                   for (std::size_t k = 0; k < pixels.size(); ++k)
                       judgePixel(judge, pixels[k], probes::renderPixel.answer(out[k]));
               }});

    const std::vector<Pixel> distinct{{8, 8, 1, 1, 8, 3},
                                      {16, 16, random.integer(0, 15), random.integer(0, 15), random.integer(4, 16),
                                       std::uint64_t(random.integer(0, 1 << 30))}};
    calls.clear();
    for (const Pixel& p : distinct)
        calls.push_back(p.call());
    checks.add({"own_offsets", calls,
               [distinct](const auto& out, Judge& judge) {
                   for (std::size_t k = 0; k < distinct.size(); ++k) {
                       const Rendered rendered = probes::renderPixel.answer(out[k]);
                       std::set<std::pair<double, double>> points;
                       for (const auto& [sx, sy] : rendered.points) points.emplace(sx, sy);
                       judge.expectTrue(tr("what.lab5.distinct", {{"samples", std::to_string(distinct[k].samples)},
                                                                  {"pixel", distinct[k].name()}}),
                                        points.size() == std::size_t(distinct[k].samples),
                                        std::to_string(distinct[k].samples), std::to_string(points.size()),
                                        tr("hint.lab5.next2d"));
                   }
               }});

    // Two pixels, each with its own sampler: the same offsets in both is a pattern reused in every
    // pixel (docs/grading.md: a mistake here, whatever its seed).
    // The first pixel is a fixed case, the second drawn (never the same pixel).
    const int otherI = random.integer(3, 15), otherJ = random.integer(0, 15);
    const std::vector<Pixel> twoPixels{{16, 16, 2, 5, 8, 11},
                                       {16, 16, otherI, otherJ, 8, std::uint64_t(random.integer(0, 1 << 30))}};
    calls.clear();
    for (const Pixel& p : twoPixels)
        calls.push_back(p.call());
    checks.add({"pixel_offsets", calls, [twoPixels](const auto& out, Judge& judge) {
                   std::vector<std::vector<std::pair<double, double>>> offsets;
                   for (std::size_t k = 0; k < twoPixels.size(); ++k) {
                       const Pixel& p = twoPixels[k];
                       offsets.emplace_back();
                       const Rendered rendered = probes::renderPixel.answer(out[k]);
                       for (const auto& [sx, sy] : rendered.points)
                           offsets.back().emplace_back(sx * p.width - p.i, sy * p.height - p.j);
                   }
                   // Offsets need samples: a pixel that traces no ray (or too few) has none to differ.
                   for (std::size_t k = 0; k < twoPixels.size(); ++k)
                       if (!judge.expectTrue(tr("what.lab5.rays_traced", {{"pixel", twoPixels[k].name()}}),
                                             offsets[k].size() == std::size_t(twoPixels[k].samples),
                                             std::to_string(twoPixels[k].samples), std::to_string(offsets[k].size()),
                                             tr("hint.lab5.one_ray")))
                           return;
                   // (i + x) / W in float, read back: the same x within 1e-5 pixel at these sizes.
                   bool same = offsets[0].size() == offsets[1].size() && !offsets[0].empty();
                   for (std::size_t k = 0; same && k < offsets[0].size(); ++k)
                       same = std::abs(offsets[0][k].first - offsets[1][k].first) <= 1e-5 &&
                              std::abs(offsets[0][k].second - offsets[1][k].second) <= 1e-5;
                   judge.expectTrue(tr("what.lab5.own_offsets", {{"pixel", twoPixels[0].name()},
                                                                 {"i", std::to_string(twoPixels[1].i)},
                                                                 {"j", std::to_string(twoPixels[1].j)}}),
                                    !same, tr("what.lab5.different_offsets"), tr("what.lab5.same_offsets"),
                                    tr("hint.lab5.own_offsets"));
               }});
}

} // namespace

RAYLAB_REGISTER_CHECKS(addChecks);

} // namespace raylab::grader
