#include "raylab/sampler.h"

#include <doctest/doctest.h>

#include <set>
#include <string>
#include <utility>

using namespace raylab;

TEST_SUITE("sampler") {

TEST_CASE("the centre sampler always answers the pixel centre") {
    PixelSampler s(SamplerKind::Center, 8, 1, 3, 4, 10);
    for (int k = 0; k < 8; ++k) CHECK(s.next2D() == glm::vec2(0.5f));
}

TEST_CASE("random samples are in [0, 1), repeat per pixel and seed, and differ between pixels") {
    PixelSampler a(SamplerKind::Random, 16, 7, 3, 4, 10), b(SamplerKind::Random, 16, 7, 3, 4, 10);
    PixelSampler c(SamplerKind::Random, 16, 7, 4, 3, 10), d(SamplerKind::Random, 16, 8, 3, 4, 10);
    double mean = 0.;
    for (int k = 0; k < 16; ++k) {
        const glm::vec2 p = a.next2D();
        CHECK(p == b.next2D());
        CHECK(p != c.next2D());
        CHECK(p != d.next2D());
        CHECK(p.x >= 0.f);
        CHECK(p.x < 1.f);
        CHECK(p.y >= 0.f);
        CHECK(p.y < 1.f);
        mean += p.x;
    }
    CHECK(mean / 16 == doctest::Approx(0.5).epsilon(0.5));
}

TEST_CASE("stratified samples put one point in each cell of the grid") {
    for (int n : {1, 4, 6, 16, 32}) {
        PixelSampler s(SamplerKind::Stratified, n, 3, 0, 0, 1);
        std::set<std::pair<int, int>> cells;
        int columns = 0, rows = 0;
        for (int r = 1; r * r <= n; ++r)
            if (n % r == 0) rows = r;
        columns = n / rows;
        for (int k = 0; k < n; ++k) {
            const glm::vec2 p = s.next2D();
            cells.insert({int(p.x * float(columns)), int(p.y * float(rows))});
        }
        CHECK_MESSAGE(cells.size() == std::size_t(n), "n = " << n);
    }
}

TEST_CASE("sampler names") {
    CHECK(samplerKindFromString("stratified") == SamplerKind::Stratified);
    CHECK(std::string(samplerName(SamplerKind::Random)) == "random");
    CHECK_FALSE(samplerKindFromString("magic").has_value());
}

}
