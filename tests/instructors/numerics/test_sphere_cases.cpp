// The catalogue's intersection cases (docs/numerics.md), on the reference solution of lab 3, with
// the textbook formula as the foil where it fails.
#include "numerics_support.h"

#include <doctest/doctest.h>

#include <cmath>
#include <initializer_list>
#include <stdexcept>

using namespace raylab;
using namespace raylab::numerics;

TEST_SUITE("numerics") {

TEST_CASE("far sphere: a ray parallel to the axis hits exactly when it passes within the radius") {
    // Sphere of radius 1 at (0, 0, D); the ray from (x, 0, 0) along +z meets it at D - sqrt(1 - x^2).
    for (float distance : {1e2f, 1e3f, 1e4f, 1e5f}) {
        const glm::vec3 centre(0.f, 0.f, distance);
        for (float x : {0.f, 0.5f, 0.9f, 0.99f, 0.999f, 1.001f, 1.01f, 1.5f}) {
            CAPTURE(distance);
            CAPTURE(x);
            HitRecord hit;
            const bool found = labHit(Ray{{x, 0.f, 0.f}, {0.f, 0.f, 1.f}}, centre, 1.f, &hit);
            CHECK(found == (x < 1.f));
            if (found)
                CHECK(double(hit.t) == doctest::Approx(double(distance) - std::sqrt(1. - double(x) * x)).epsilon(1e-7));
        }
    }
}

TEST_CASE("far sphere: the textbook discriminant is rounding noise 10^4 radii away") {
    // b^2 = 4e8 and 4ac = 4 (1e8 + x^2 - 1) agree to float's 24 bits: the foil sees the sphere
    // from 1.5 radii off its axis, where the lab code rightly sees nothing.
    const glm::vec3 centre(0.f, 0.f, 1e4f);
    const Ray offAxis{{1.5f, 0.f, 0.f}, {0.f, 0.f, 1.f}};
    CHECK(textbook(offAxis, centre, 1.f).hit);
    CHECK_FALSE(labHit(offAxis, centre, 1.f));
}

TEST_CASE("far sphere: rays near it are classified like the long double truth; the textbook's are not") {
    // The rates that docs/numerics.md quotes (raylab numerics, 200000 rays; here 20000).
    const Misclassified at100 = misclassified(raysNearSphere(1e2, 1., 20000));
    CHECK(at100.lab == 0.);
    const Misclassified at1000 = misclassified(raysNearSphere(1e3, 1., 20000));
    CHECK(at1000.lab <= 1e-4);
    CHECK(at1000.textbook > 0.005); // about 1.4%
    const Misclassified at10000 = misclassified(raysNearSphere(1e4, 1., 20000));
    CHECK(at10000.lab <= 2e-4);
    CHECK(at10000.textbook > 0.5); // about 75%: every ray "hits"
}

TEST_CASE("tiny and huge spheres: radius 10^-3 to 10^3 at 10 radii behave the same, scaled") {
    for (float r : {1e-3f, 1e-1f, 1.f, 1e1f, 1e3f}) {
        const glm::vec3 centre(0.f, 0.f, 10.f * r);
        for (float x : {0.f, 0.6f, 0.999f, 1.001f}) {
            CAPTURE(r);
            CAPTURE(x);
            HitRecord hit;
            const bool found = labHit(Ray{{x * r, 0.f, 0.f}, {0.f, 0.f, 1.f}}, centre, r, &hit);
            REQUIRE(found == (x < 1.f));
            if (found) CHECK(double(hit.t) / r == doctest::Approx(10. - std::sqrt(1. - double(x) * x)).epsilon(1e-6));
        }
    }
}

TEST_CASE("tangent and grazing rays: exactly on the silhouette it hits, one float further it misses") {
    for (float distance : {3.f, 1e4f}) {
        CAPTURE(distance);
        const glm::vec3 centre(0.f, 0.f, distance);
        HitRecord hit;
        REQUIRE(labHit(Ray{{1.f, 0.f, 0.f}, {0.f, 0.f, 1.f}}, centre, 1.f, &hit));
        CHECK(hit.t == distance); // the tangent point, exactly: l = (1, 0, 0), disc = 0
        CHECK_FALSE(labHit(Ray{{std::nextafter(1.f, 2.f), 0.f, 0.f}, {0.f, 0.f, 1.f}}, centre, 1.f));
    }
    // The foil sees a sphere 10^4 away from 1.0001 radii off its axis.
    CHECK(textbook(Ray{{1.0001f, 0.f, 0.f}, {0.f, 0.f, 1.f}}, {0.f, 0.f, 1e4f}, 1.f).hit);
}

TEST_CASE("ray origin inside the sphere: the hit is the far side, ahead of the origin") {
    const glm::vec3 centre(0.f, 0.f, 3.f);
    HitRecord hit;
    REQUIRE(labHit(Ray{centre, {0.f, 0.f, 1.f}}, centre, 1.f, &hit));
    CHECK(hit.t == 1.f);
    REQUIRE(labHit(Ray{centre + glm::vec3(0.5f, 0.f, 0.f), {0.f, 0.f, 1.f}}, centre, 1.f, &hit));
    CHECK(double(hit.t) == doctest::Approx(std::sqrt(0.75)).epsilon(1e-7));
    CHECK(glm::length(hit.position - centre) == doctest::Approx(1.f).epsilon(1e-6));
    // Inside a huge sphere whose near root is -10^3: still the far side.
    REQUIRE(labHit(Ray{{0.f, 0.f, 0.f}, {0.f, 0.f, 1.f}}, {0.f, 0.f, 1.f}, 1e3f, &hit));
    CHECK(hit.t == 1001.f);
}

TEST_CASE("sphere behind the camera, and both roots behind the origin: no hit") {
    CHECK_FALSE(labHit(Ray{{0.f, 0.f, 0.f}, {0.f, 0.f, 1.f}}, {0.f, 0.f, -3.f}, 1.f));
    CHECK_FALSE(labHit(Ray{{0.f, 0.f, 0.f}, {0.f, 0.f, 1.f}}, {0.f, 0.f, -1e4f}, 1.f));
    // Roots at -4 and -2: both behind.
    CHECK_FALSE(labHit(Ray{{0.f, 0.f, 0.f}, {0.f, 0.f, -1.f}}, {0.f, 0.f, 3.f}, 1.f));
    // Just past the far side: roots at -2.5 and -0.5.
    CHECK_FALSE(labHit(Ray{{0.f, 0.f, 4.5f}, {0.f, 0.f, 1.f}}, {0.f, 0.f, 3.f}, 1.f));
}

TEST_CASE("tMin and tMax: inclusive bounds, the near root first, the far one when the near is outside") {
    const SphereGeometry sphere({0.f, 0.f, 3.f}, 1.f, Color(1.f));
    const Ray ray{{0.f, 0.f, 0.f}, {0.f, 0.f, 1.f}}; // roots 2 and 4, exact
    HitRecord hit;
    REQUIRE(sphere.intersect(ray, 2.f, 3.f, hit)); // a hit exactly at tMin counts
    CHECK(hit.t == 2.f);
    REQUIRE(sphere.intersect(ray, 0.f, 2.f, hit)); // and exactly at tMax
    CHECK(hit.t == 2.f);
    REQUIRE(sphere.intersect(ray, std::nextafter(2.f, 3.f), kInf, hit)); // just past the near root
    CHECK(hit.t == 4.f);
    CHECK_FALSE(sphere.intersect(ray, 0.f, std::nextafter(2.f, 0.f), hit));
    CHECK_FALSE(sphere.intersect(ray, std::nextafter(4.f, 5.f), kInf, hit));
    CHECK_FALSE(sphere.intersect(ray, 3.f, 3.5f, hit)); // between the roots
}

TEST_CASE("a direction that is not unit changes t, never the hit point") {
    const glm::vec3 centre(0.3f, -0.2f, 5.f);
    const glm::vec3 unit = glm::normalize(glm::vec3(0.05f, -0.03f, 1.f));
    HitRecord reference;
    REQUIRE(labHit(Ray{{0.f, 0.f, 0.f}, unit}, centre, 1.f, &reference));
    for (float scale : {1e-3f, 0.5f, 3.f, 1e3f}) {
        CAPTURE(scale);
        HitRecord hit;
        REQUIRE(labHit(Ray{{0.f, 0.f, 0.f}, unit * scale}, centre, 1.f, &hit));
        CHECK(double(hit.t) * scale == doctest::Approx(double(reference.t)).epsilon(1e-6));
        CHECK(glm::length(hit.position - reference.position) <= 1e-5f);
    }
    // Far away too: 10^4 radii, direction scaled by 10^3.
    const glm::vec3 far(0.f, 0.f, 1e4f);
    HitRecord a, b;
    REQUIRE(labHit(Ray{{0.5f, 0.f, 0.f}, {0.f, 0.f, 1.f}}, far, 1.f, &a));
    REQUIRE(labHit(Ray{{0.5f, 0.f, 0.f}, {0.f, 0.f, 1e3f}}, far, 1.f, &b));
    CHECK(glm::length(a.position - b.position) <= 1e-3f); // an ulp of 10^4
}

TEST_CASE("NaN, infinite or zero directions and origins never hit (no NaN t reaches a pixel)") {
    const glm::vec3 centre(0.f, 0.f, 3.f);
    for (const Ray& ray : {Ray{{0.f, 0.f, 0.f}, {kNaN, 0.f, 1.f}}, Ray{{0.f, 0.f, 0.f}, {0.f, 0.f, 0.f}},
                           Ray{{kNaN, 0.f, 0.f}, {0.f, 0.f, 1.f}}, Ray{{0.f, 0.f, -kInf}, {0.f, 0.f, 1.f}},
                           Ray{{0.f, 0.f, 0.f}, {kInf, 0.f, 1.f}}}) {
        HitRecord hit;
        hit.t = 42.f;
        CHECK_FALSE(SphereGeometry(centre, 1.f, Color(1.f)).intersect(ray, 0.f, kInf, hit));
        CHECK(hit.t == 42.f);
    }
}

TEST_CASE("spheres without meaning are refused, naming the parameter and its value") {
    CHECK_THROWS_WITH_AS(SphereGeometry({0.f, 0.f, 3.f}, 0.f, Color(1.f)), doctest::Contains("radius = 0 has no meaning"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(SphereGeometry({0.f, 0.f, 3.f}, -1.f, Color(1.f)), doctest::Contains("radius = -1 has no meaning"), std::invalid_argument);
    CHECK_THROWS_AS(SphereGeometry({0.f, 0.f, 3.f}, kNaN, Color(1.f)), std::invalid_argument);
    CHECK_THROWS_AS(SphereGeometry({0.f, 0.f, 3.f}, kInf, Color(1.f)), std::invalid_argument);
    CHECK_THROWS_WITH_AS(SphereGeometry({0.f, 0.f, 3.f}, 1e20f, Color(1.f)), doctest::Contains("square overflows"),
                         std::invalid_argument);
    CHECK_NOTHROW(SphereGeometry({0.f, 0.f, 3.f}, 1e18f, Color(1.f)));
    CHECK_THROWS_WITH_AS(SphereGeometry({0.f, kNaN, 3.f}, 1.f, Color(1.f)), doctest::Contains("center = (0, nan, 3) is not finite"),
                         std::invalid_argument);
}

}
