// The reference solution of lab 3 against exact intersection distances.
#include "raylab/integrator.h"
#include "raylab/scene.h"

#include <doctest/doctest.h>
#include <glm/geometric.hpp>

#include <limits>

using namespace raylab;

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
const SphereGeometry kUnitAt3({0.f, 0.f, 3.f}, 1.f, {0.f, 0.f, 1.f});

} // namespace

TEST_SUITE("sphere") {

TEST_CASE("a ray through the centre hits the near side first") {
    HitRecord hit;
    REQUIRE(kUnitAt3.intersect(Ray{{0.f, 0.f, 0.f}, {0.f, 0.f, 1.f}}, 0.f, kInf, hit));
    CHECK(hit.t == 2.f);
    CHECK(hit.position == glm::vec3(0.f, 0.f, 2.f));
}

TEST_CASE("the interval [tMin, tMax] selects the root") {
    const Ray ray{{0.f, 0.f, 0.f}, {0.f, 0.f, 1.f}};
    HitRecord hit;
    REQUIRE(kUnitAt3.intersect(ray, 2.5f, kInf, hit)); // past the near side: the far one
    CHECK(hit.t == 4.f);
    CHECK_FALSE(kUnitAt3.intersect(ray, 0.f, 1.9f, hit));
    CHECK_FALSE(kUnitAt3.intersect(ray, 4.1f, kInf, hit));
    REQUIRE(kUnitAt3.intersect(ray, 2.f, 2.f, hit)); // both bounds are inclusive
    CHECK(hit.t == 2.f);
}

TEST_CASE("a miss leaves the hit record alone") {
    HitRecord hit;
    hit.t = 42.f;
    CHECK_FALSE(kUnitAt3.intersect(Ray{{0.f, 2.f, 0.f}, {0.f, 0.f, 1.f}}, 0.f, kInf, hit));
    CHECK(hit.t == 42.f);
}

TEST_CASE("inside the sphere the ray hits the far side; behind the ray it hits nothing") {
    HitRecord hit;
    REQUIRE(kUnitAt3.intersect(Ray{{0.f, 0.f, 3.f}, {1.f, 0.f, 0.f}}, 0.f, kInf, hit));
    CHECK(hit.t == 1.f);
    CHECK(hit.position == glm::vec3(1.f, 0.f, 3.f));
    CHECK_FALSE(kUnitAt3.intersect(Ray{{0.f, 0.f, 0.f}, {0.f, 0.f, -1.f}}, 0.f, kInf, hit));
}

TEST_CASE("a tangent ray touches the sphere once") {
    HitRecord hit;
    REQUIRE(kUnitAt3.intersect(Ray{{1.f, 0.f, 0.f}, {0.f, 0.f, 1.f}}, 0.f, kInf, hit));
    CHECK(hit.t == doctest::Approx(3.f).epsilon(1e-3));
    CHECK_FALSE(kUnitAt3.intersect(Ray{{1.001f, 0.f, 0.f}, {0.f, 0.f, 1.f}}, 0.f, kInf, hit));
}

TEST_CASE("a direction that is not unit changes t, not the point") {
    HitRecord unit, scaled;
    REQUIRE(kUnitAt3.intersect(Ray{{0.f, 0.f, 0.f}, glm::normalize(glm::vec3(0.1f, 0.2f, 1.f))}, 0.f, kInf, unit));
    REQUIRE(kUnitAt3.intersect(Ray{{0.f, 0.f, 0.f}, 5.f * glm::normalize(glm::vec3(0.1f, 0.2f, 1.f))}, 0.f, kInf, scaled));
    CHECK(scaled.t == doctest::Approx(unit.t / 5.f).epsilon(1e-6));
    CHECK(glm::length(scaled.position - unit.position) < 1e-6f);
}

TEST_CASE("the normal is the unit vector from the centre") {
    CHECK(kUnitAt3.computeNormal({0.f, 0.f, 2.f}) == glm::vec3(0.f, 0.f, -1.f));
    const SphereGeometry big({1.f, 2.f, 3.f}, 2.f, Color(1.f));
    CHECK(big.computeNormal({1.f, 4.f, 3.f}) == glm::vec3(0.f, 1.f, 0.f));
}

TEST_CASE("the scene keeps the nearest of several hits") {
    Scene scene;
    scene.add(SphereGeometry(glm::vec3(0.f, 0.f, 10.f), 1.f, Color(1.f, 0.f, 0.f)));
    scene.add(SphereGeometry(glm::vec3(0.f, 0.f, 5.f), 1.f, Color(0.f, 1.f, 0.f)));
    HitRecord hit;
    REQUIRE(scene.intersect(Ray{{0.f, 0.f, 0.f}, {0.f, 0.f, 1.f}}, hit));
    CHECK(hit.t == 4.f);
    CHECK(hit.object == &scene.all<SphereGeometry>()[1]);
    // Bounded like SphereGeometry::intersect(ray, tMin, tMax, hit): past the first sphere, the second.
    REQUIRE(scene.intersect(Ray{{0.f, 0.f, 0.f}, {0.f, 0.f, 1.f}}, 7.f, 100.f, hit));
    CHECK(hit.t == 9.f);
    CHECK(hit.object == &scene.all<SphereGeometry>()[0]);
    CHECK_FALSE(scene.intersect(Ray{{0.f, 0.f, 0.f}, {0.f, 0.f, 1.f}}, 0.f, 3.5f, hit));
}

TEST_CASE("the integrator's shadings") {
    const Scene scene = makeTp1Scene();
    const Ray centre{{0.f, 0.f, 0.f}, {0.f, 0.f, 1.f}};
    const Ray miss{{0.f, 0.f, 0.f}, {0.f, 1.f, 0.f}};
    CHECK(RayCastIntegrator(Shading::Flat).Li(scene, miss) == scene.background);
    CHECK(RayCastIntegrator(Shading::Flat).Li(scene, centre) == Color(0.f, 0.f, 1.f));
    CHECK(RayCastIntegrator(Shading::Cosine).Li(scene, centre) == Color(0.f, 0.f, 1.f)); // facing: cos = 1
    const Color placeholder = RayCastIntegrator(Shading::PlaceholderNormal).Li(scene, centre);
    CHECK(placeholder.b == doctest::Approx(1.f / std::sqrt(3.f)));
    // Off-centre, the colour is scaled by -d . n at the hit point.
    const Ray oblique{{0.f, 0.f, 0.f}, glm::normalize(glm::vec3(0.f, std::sqrt(3.f) / 2.f, 2.5f))};
    const Color c = RayCastIntegrator(Shading::Cosine).Li(scene, oblique);
    HitRecord hit;
    REQUIRE(scene.intersect(oblique, hit));
    CHECK(c.b == doctest::Approx(-glm::dot(oblique.direction, (hit.position - glm::vec3(0.f, 0.f, 3.f)))).epsilon(1e-5));
    CHECK(DirectionIntegrator().Li(scene, centre) == Color(0.5f, 0.5f, 1.f));
}

}
