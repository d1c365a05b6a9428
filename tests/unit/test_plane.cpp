// Planes: the intersection against exact distances, and the rays it must refuse.
#include "raylab/plane.h"

#include <doctest/doctest.h>

#include <limits>
#include <stdexcept>

using namespace raylab;

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
// The ground y = -1, its normal up, given unnormalized.
const Plane kGround({3.f, -1.f, 5.f}, {0.f, 2.f, 0.f}, {0.5f, 0.5f, 0.5f});

} // namespace

TEST_SUITE("plane") {

TEST_CASE("a ray down to the ground meets it at the exact distance") {
    HitRecord hit;
    REQUIRE(kGround.intersect(Ray{{0.f, 3.f, 0.f}, {0.f, -1.f, 0.f}}, 0.f, kInf, hit));
    CHECK(hit.t == 4.f);
    CHECK(hit.position == glm::vec3(0.f, -1.f, 0.f));
    REQUIRE(kGround.intersect(Ray{{0.f, 1.f, 0.f}, {0.f, -1.f, 1.f}}, 0.f, kInf, hit)); // unnormalized: t in its units
    CHECK(hit.t == 2.f);
    CHECK(hit.position == glm::vec3(0.f, -1.f, 2.f));
    // From below too: a plane has two sides.
    REQUIRE(kGround.intersect(Ray{{0.f, -3.f, 0.f}, {0.f, 1.f, 0.f}}, 0.f, kInf, hit));
    CHECK(hit.t == 2.f);
}

TEST_CASE("the interval [tMin, tMax] is inclusive, and a miss leaves the hit record alone") {
    const Ray ray{{0.f, 3.f, 0.f}, {0.f, -1.f, 0.f}};
    HitRecord hit;
    hit.t = 42.f;
    CHECK_FALSE(kGround.intersect(ray, 0.f, 3.99f, hit));
    CHECK_FALSE(kGround.intersect(ray, 4.01f, kInf, hit));
    CHECK(hit.t == 42.f);
    REQUIRE(kGround.intersect(ray, 4.f, 4.f, hit));
    CHECK(hit.t == 4.f);
    CHECK_FALSE(kGround.intersect(Ray{{0.f, 3.f, 0.f}, {0.f, 1.f, 0.f}}, 0.f, kInf, hit)); // behind the ray
    CHECK(kGround.hits(ray, 4.f, 4.f));
    CHECK_FALSE(kGround.hits(ray, 0.f, 3.99f));
}

TEST_CASE("a parallel ray, a ray in the plane and a NaN ray miss") {
    HitRecord hit;
    hit.t = 42.f;
    CHECK_FALSE(kGround.intersect(Ray{{0.f, 3.f, 0.f}, {1.f, 0.f, 0.f}}, 0.f, kInf, hit));  // parallel, above
    CHECK_FALSE(kGround.intersect(Ray{{0.f, -1.f, 0.f}, {1.f, 0.f, 1.f}}, 0.f, kInf, hit)); // lying in it: 0 / 0
    CHECK_FALSE(kGround.intersect(Ray{{0.f, kNaN, 0.f}, {0.f, -1.f, 0.f}}, 0.f, kInf, hit));
    CHECK_FALSE(kGround.intersect(Ray{{0.f, 3.f, 0.f}, {0.f, kNaN, 0.f}}, 0.f, kInf, hit));
    CHECK_FALSE(kGround.intersect(Ray{{0.f, 3.f, 0.f}, {0.f, 0.f, 0.f}}, 0.f, kInf, hit)); // no direction
    CHECK_FALSE(kGround.intersect(Ray{{0.f, kInf, 0.f}, {0.f, -1.f, 0.f}}, 0.f, kInf, hit)); // t would be infinite
    CHECK_FALSE(kGround.intersect(Ray{{0.f, 3.f, 0.f}, {0.f, -1.f, 0.f}}, kNaN, kInf, hit));
    CHECK(hit.t == 42.f);
    CHECK_FALSE(kGround.hits(Ray{{0.f, -1.f, 0.f}, {1.f, 0.f, 0.f}}, 0.f, kInf));
    // Nearly parallel still meets it, far away.
    REQUIRE(kGround.intersect(Ray{{0.f, 0.f, 0.f}, {1.f, -1e-6f, 0.f}}, 0.f, kInf, hit));
    CHECK(hit.t == doctest::Approx(1e6).epsilon(1e-6));
}

TEST_CASE("its normal is the unit normal given, on both sides; a normal without direction is refused") {
    CHECK(kGround.normal() == glm::vec3(0.f, 1.f, 0.f));
    CHECK(kGround.computeNormal({7.f, -1.f, 7.f}) == glm::vec3(0.f, 1.f, 0.f));
    CHECK(Plane({0.f, 0.f, 0.f}, {0.f, 0.f, -1e-30f}, Color(1.f)).normal() == glm::vec3(0.f, 0.f, -1.f));
    CHECK(kGround.color() == Color(0.5f));
    CHECK_THROWS_WITH_AS(Plane({0.f, 0.f, 0.f}, {0.f, 0.f, 0.f}, Color(1.f)), doctest::Contains("has no direction"),
                         std::invalid_argument);
    CHECK_THROWS_AS(Plane({0.f, 0.f, 0.f}, {kNaN, 1.f, 0.f}, Color(1.f)), std::invalid_argument);
    CHECK_THROWS_AS(Plane({kInf, 0.f, 0.f}, {0.f, 1.f, 0.f}, Color(1.f)), std::invalid_argument);
}

} // TEST_SUITE
