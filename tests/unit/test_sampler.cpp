#include "raylab/sampler.h"
#include "src/low_discrepancy.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <utility>
#include <vector>

using namespace raylab;

namespace {

constexpr SamplerKind kPointSamplers[] = {SamplerKind::Random, SamplerKind::Stratified, SamplerKind::Grid,
                                          SamplerKind::Sobol, SamplerKind::R2};

std::vector<glm::vec2> pointsOf(SamplerKind kind, int n, std::uint64_t seed = 3, int i = 5, int j = 7) {
    PixelSampler s(kind, n, seed, i, j, 100);
    std::vector<glm::vec2> points;
    for (int k = 0; k < n; ++k) points.push_back(s.next2D());
    return points;
}

// The star discrepancy measured on anchored boxes [0, x) x [0, y) with corners on a 64 x 64 grid
// (and at the points themselves): how far the share of points in a box is from its area.
double starDiscrepancy(const std::vector<glm::vec2>& points) {
    std::vector<double> xs, ys;
    for (int k = 1; k <= 64; ++k) {
        xs.push_back(k / 64.);
        ys.push_back(k / 64.);
    }
    for (const glm::vec2& p : points) {
        xs.push_back(p.x);
        ys.push_back(p.y);
    }
    double worst = 0.;
    const double n = double(points.size());
    for (double x : xs)
        for (double y : ys) {
            int open = 0, closed = 0;
            for (const glm::vec2& p : points) {
                open += p.x < x && p.y < y;
                closed += p.x <= x && p.y <= y;
            }
            worst = std::max({worst, std::abs(open / n - x * y), std::abs(closed / n - x * y)});
        }
    return worst;
}

} // namespace

TEST_SUITE("sampler") {

TEST_CASE("the centre sampler always answers the pixel centre, drawing no random numbers") {
    PixelSampler s(SamplerKind::Center, 8, 1, 3, 4, 10);
    for (int k = 0; k < 8; ++k) CHECK(s.next2D() == glm::vec2(0.5f));
    CHECK(s.randomNumbersDrawn() == 0);
}

TEST_CASE("every sampler's points are in [0, 1), for many pixels and counts") {
    for (SamplerKind kind : kPointSamplers)
        for (int n : {1, 3, 4, 7, 16, 33, 256})
            for (int pixel = 0; pixel < 50; ++pixel)
                for (const glm::vec2& p : pointsOf(kind, n, 11, pixel, pixel * 3)) {
                    REQUIRE_MESSAGE(p.x >= 0.f, samplerName(kind));
                    REQUIRE_MESSAGE(p.x < 1.f, samplerName(kind));
                    REQUIRE_MESSAGE(p.y >= 0.f, samplerName(kind));
                    REQUIRE_MESSAGE(p.y < 1.f, samplerName(kind));
                }
}

TEST_CASE("the samples repeat per pixel and seed, and differ between pixels and seeds") {
    for (SamplerKind kind : kPointSamplers) {
        INFO(samplerName(kind));
        CHECK(pointsOf(kind, 16) == pointsOf(kind, 16));
        if (kind == SamplerKind::Grid) {
            // The grid is the same in every pixel: it has nothing random.
            CHECK(pointsOf(kind, 16, 3, 5, 7) == pointsOf(kind, 16, 4, 6, 8));
        } else {
            CHECK(pointsOf(kind, 16, 3, 5, 7) != pointsOf(kind, 16, 3, 6, 7));
            CHECK(pointsOf(kind, 16, 3, 5, 7) != pointsOf(kind, 16, 4, 5, 7));
        }
    }
}

TEST_CASE("how many random numbers each sampler draws") {
    const int n = 16;
    auto drawn = [&](SamplerKind kind) {
        PixelSampler s(kind, n, 1, 2, 3, 10);
        for (int k = 0; k < n; ++k) s.next2D();
        return s.randomNumbersDrawn();
    };
    CHECK(drawn(SamplerKind::Center) == 0);
    CHECK(drawn(SamplerKind::Grid) == 0);
    CHECK(drawn(SamplerKind::Random) == 2 * n);
    CHECK(drawn(SamplerKind::Stratified) == 2 * n);
    CHECK(drawn(SamplerKind::Sobol) == 2); // the pixel's two scrambling seeds
    CHECK(drawn(SamplerKind::R2) == 2);    // the pixel's offset
}

TEST_CASE("stratified and grid samples put one point in each cell of the grid") {
    for (SamplerKind kind : {SamplerKind::Stratified, SamplerKind::Grid})
        for (int n : {1, 4, 6, 16, 32}) {
            int columns = 0, rows = 0;
            for (int r = 1; r * r <= n; ++r)
                if (n % r == 0) rows = r;
            columns = n / rows;
            std::set<std::pair<int, int>> cells;
            for (const glm::vec2& p : pointsOf(kind, n)) cells.insert({int(p.x * float(columns)), int(p.y * float(rows))});
            CHECK_MESSAGE(cells.size() == std::size_t(n), samplerName(kind) << ", n = " << n);
        }
}

TEST_CASE("grid samples are the cell centres") {
    const std::vector<glm::vec2> p = pointsOf(SamplerKind::Grid, 4);
    CHECK(p == std::vector<glm::vec2>{{0.25f, 0.25f}, {0.75f, 0.25f}, {0.25f, 0.75f}, {0.75f, 0.75f}});
}

TEST_CASE("the Sobol' sequence's first points, unscrambled, in index (not Gray code) order") {
    using lowdiscrepancy::sobol;
    const double x[] = {0., 0.5, 0.25, 0.75, 0.125, 0.625, 0.375, 0.875};
    const double y[] = {0., 0.5, 0.75, 0.25, 0.625, 0.125, 0.375, 0.875};
    for (std::uint32_t k = 0; k < 8; ++k) {
        CHECK(sobol(k, 0) * 0x1p-32 == x[k]);
        CHECK(sobol(k, 1) * 0x1p-32 == y[k]);
    }
}

TEST_CASE("scrambled Sobol' points are a (0, m, 2)-net: one point in every elementary box of area 1/2^m") {
    for (int m = 0; m <= 8; ++m)
        for (int pixel = 0; pixel < 4; ++pixel) {
            const int n = 1 << m;
            const std::vector<glm::vec2> points = pointsOf(SamplerKind::Sobol, n, 9, pixel, 2 * pixel);
            for (int a = 0; a <= m; ++a) { // boxes 2^-a wide and 2^-(m - a) high
                std::set<std::pair<int, int>> boxes;
                for (const glm::vec2& p : points) boxes.insert({int(p.x * float(1 << a)), int(p.y * float(1 << (m - a)))});
                CHECK_MESSAGE(boxes.size() == std::size_t(n), "m = " << m << ", a = " << a);
            }
        }
}

TEST_CASE("the sobol sampler serves owenScramble(sobol(k, d), seed_d) for k = 0, 1, 2 ..., its seeds the pixel's first draws") {
    using lowdiscrepancy::owenScramble;
    using lowdiscrepancy::sobol;
    const std::uint64_t seed = 5;
    const int i = 3, j = 2, width = 10;
    PixelSampler sampler(SamplerKind::Sobol, 4096, seed, i, j, width);
    Pcg32 rng(seed, std::uint64_t(j) * width + i);
    const std::uint32_t scramble[2] = {rng.nextUInt(), rng.nextUInt()};
    int differing = 0;
    for (std::uint32_t k = 0; k < 5000; ++k) { // past the 4096 it was made for: the sequence goes on
        const glm::vec2 p = sampler.next2D();
        differing += p.x != float(owenScramble(sobol(k, 0), scramble[0]) >> 8) * 0x1p-24f;
        differing += p.y != float(owenScramble(sobol(k, 1), scramble[1]) >> 8) * 0x1p-24f;
    }
    CHECK(differing == 0);
}

TEST_CASE("Owen scrambling permutes: distinct inputs stay distinct, and it depends on the seed") {
    using lowdiscrepancy::owenScramble;
    std::set<std::uint32_t> seen;
    for (std::uint32_t k = 0; k < 4096; ++k) seen.insert(owenScramble(k << 20, 77) >> 20);
    CHECK(seen.size() == 4096); // a bijection of the top 12 bits
    CHECK(owenScramble(0x40000000u, 1) != owenScramble(0x40000000u, 2));
}

TEST_CASE("sobol and r2 have a low discrepancy, random points a much larger one") {
    const int n = 256;
    double random = 0., sobol = 0., r2 = 0.;
    for (int pixel = 0; pixel < 4; ++pixel) {
        random = std::max(random, starDiscrepancy(pointsOf(SamplerKind::Random, n, 5, pixel, 0)));
        sobol = std::max(sobol, starDiscrepancy(pointsOf(SamplerKind::Sobol, n, 5, pixel, 0)));
        r2 = std::max(r2, starDiscrepancy(pointsOf(SamplerKind::R2, n, 5, pixel, 0)));
    }
    MESSAGE("star discrepancy of 256 points: random ", random, ", sobol ", sobol, ", r2 ", r2);
    // Low discrepancy is O(log^2 N / N), 0.01 to 0.03 here; random points are O(1 / sqrt N).
    CHECK(sobol < 0.03);
    CHECK(r2 < 0.03);
    CHECK(random > 2. * std::max(sobol, r2));
}

TEST_CASE("sampler names") {
    for (SamplerKind kind : kAllSamplerKinds) CHECK(samplerKindFromString(samplerName(kind)) == kind);
    CHECK(samplerKindFromString("stratified") == SamplerKind::Stratified);
    CHECK(std::string(samplerName(SamplerKind::R2)) == "r2");
    CHECK_FALSE(samplerKindFromString("magic").has_value());
}

}
