// Lab 3's function checks: intersection distances of chosen rays (with the hard cases of
// docs/numerics.md that are fair to ask), normals and shading.
#include "checks/check_support.h"

#include "raylab/integrator.h"
#include "raylab/scene.h"

#include <cmath>
#include <limits>

using namespace raylab;
using namespace raylab::checks;

namespace {

const SphereGeometry kSphere(glm::vec3(0.f, 0.f, 3.f), 1.f, Color(0.f, 0.f, 1.f));
constexpr float kInf = std::numeric_limits<float>::infinity();

// Expects a hit at t (and its point); returns false after reporting otherwise.
bool expectHit(const std::string& what, const SphereGeometry& sphere, const Ray& ray, float tMin, float tMax, float t,
               float tolerance, const std::string& hint) {
    HitRecord hit;
    if (!sphere.intersect(ray, tMin, tMax, hit)) {
        fail(what, "a hit at t = " + show(t), "no hit", hint);
        return false;
    }
    return expectNear(what + ", t", hit.t, t, tolerance, hint) &&
           expectNear(what + ", hit.position", hit.position, ray.at(t), tolerance * 2.f,
                      "store hit.position = ray.at(hit.t)");
}

bool expectMiss(const std::string& what, const SphereGeometry& sphere, const Ray& ray, float tMin, float tMax,
                const std::string& hint) {
    HitRecord hit;
    hit.t = -7.f;
    const bool found = sphere.intersect(ray, tMin, tMax, hit);
    if (found) fail(what, "no hit", "a hit at t = " + show(hit.t), hint);
    else if (hit.t != -7.f) fail(what + " (the hit record)", "left alone", "t changed to " + show(hit.t),
                                 "write into hit only when you return true");
    return !found;
}

} // namespace

TEST_SUITE("lab3") {

TEST_CASE("intersect: a ray through the centre hits the near side") {
    expectHit("ray from the origin along +z", kSphere, Ray{{0.f, 0.f, 0.f}, {0.f, 0.f, 1.f}}, 0.f, kInf, 2.f, 1e-5f,
              "solve a t^2 + 2 b' t + c' = 0 with a = d.d, b' = (o - c).d, c' = |o - c|^2 - r^2; keep the smaller root");
}

TEST_CASE("intersect: a ray beside the sphere misses") {
    expectMiss("ray from (2, 0, 0) along +z", kSphere, Ray{{2.f, 0.f, 0.f}, {0.f, 0.f, 1.f}}, 0.f, kInf,
               "a negative discriminant means no real root: return false");
}

TEST_CASE("intersect: a tangent ray touches the sphere") {
    expectHit("ray from (1, 0, 0) along +z, tangent at (1, 0, 3)", kSphere, Ray{{1.f, 0.f, 0.f}, {0.f, 0.f, 1.f}}, 0.f,
              kInf, 3.f, 1e-4f, "a zero discriminant is a (double) root: test disc < 0 for a miss, not disc <= 0");
}

TEST_CASE("intersect: from inside the sphere the far root is the hit") {
    expectHit("ray from the centre (0, 0, 3) along +z", kSphere, Ray{{0.f, 0.f, 3.f}, {0.f, 0.f, 1.f}}, 0.f, kInf, 1.f,
              1e-5f, "when the smaller root is below tMin, take the larger one if it is in [tMin, tMax]");
}

TEST_CASE("intersect: a sphere behind the ray is not hit") {
    expectMiss("ray from (0, 0, 5) along +z, sphere behind", kSphere, Ray{{0.f, 0.f, 5.f}, {0.f, 0.f, 1.f}}, 0.f, kInf,
               "both roots are negative: a ray is a half-line, it sees nothing behind its origin");
}

TEST_CASE("intersect: tMin and tMax bound the hit") {
    const Ray ray{{0.f, 0.f, 0.f}, {0.f, 0.f, 1.f}};
    expectMiss("tMax = 1.5, before the sphere", kSphere, ray, 0.f, 1.5f, "a root beyond tMax does not count");
    expectHit("tMin = 2.5, past the near side", kSphere, ray, 2.5f, kInf, 4.f, 1e-5f,
              "a root below tMin does not count: try the far root");
}

TEST_CASE("intersect: a direction that is not unit length") {
    expectHit("ray from the origin along (0, 0, 2)", kSphere, Ray{{0.f, 0.f, 0.f}, {0.f, 0.f, 2.f}}, 0.f, kInf, 1.f,
              1e-5f, "keep a = d.d in the quadratic: t is then in units of |d|, and ray.at(t) is the same point");
}

TEST_CASE("intersect: a sphere 1000 radii away") {
    const SphereGeometry far(glm::vec3(0.f, 0.f, 1000.f), 1.f, Color(1.f));
    expectHit("ray at 0.5 radius from the centre line", far, Ray{{0.5f, 0.f, 0.f}, {0.f, 0.f, 1.f}}, 0.f, kInf,
              1000.f - std::sqrt(0.75f), 2e-3f,
              "b'^2 - c' subtracts two numbers near 10^6 and loses digits: the handout's stable form avoids it");
    expectMiss("ray at 1.5 radii from the centre line", far, Ray{{1.5f, 0.f, 0.f}, {0.f, 0.f, 1.f}}, 0.f, kInf,
               "a ray that passes at 1.5 radii misses, however far the sphere is");
}

TEST_CASE("intersect: a sphere 10000 radii away keeps its silhouette") {
    const SphereGeometry far(glm::vec3(0.f, 0.f, 10000.f), 1.f, Color(1.f));
    const char* hint = "at 10^4 radii the textbook discriminant b'^2 - c' is lost to rounding; compute it as "
                       "r^2 - |oc - (oc.d / d.d) d|^2 (Ray Tracing Gems, chapter 7; see the handout)";
    expectMiss("ray at 1.1 radii from the centre line", far, Ray{{1.1f, 0.f, 0.f}, {0.f, 0.f, 1.f}}, 0.f, kInf, hint);
    expectHit("ray at 0.9 radius from the centre line", far, Ray{{0.9f, 0.f, 0.f}, {0.f, 0.f, 1.f}}, 0.f, kInf,
              10000.f - std::sqrt(0.19f), 0.02f, hint);
}

TEST_CASE("computeNormal: unit and pointing outwards") {
    expectNear("normal at (0, 0, 2)", kSphere.computeNormal({0.f, 0.f, 2.f}), glm::vec3(0.f, 0.f, -1.f), 1e-6f,
               "n = (p - centre) / radius: it points from the centre outwards");
    const SphereGeometry big(glm::vec3(1.f, 2.f, 3.f), 2.f, Color(1.f));
    expectNear("normal at (1, 2, 5) of a sphere of radius 2", big.computeNormal({1.f, 2.f, 5.f}),
               glm::vec3(0.f, 0.f, 1.f), 1e-6f, "divide by the radius so the normal has length 1");
}

TEST_CASE("Li: flat shading sees the sphere's colour or the background") {
    const Scene scene = makeTp1Scene();
    const RayCastIntegrator flat(Shading::Flat);
    expectNear("flat, ray along +z", flat.Li(scene, Ray{{0.f, 0.f, 0.f}, {0.f, 0.f, 1.f}}), Color(0.f, 0.f, 1.f), 1e-6f,
               "on a hit return hit.object->color()");
    expectNear("flat, ray along +x (a miss)", flat.Li(scene, Ray{{0.f, 0.f, 0.f}, {1.f, 0.f, 0.f}}), scene.background,
               1e-6f, "a ray that hits nothing sees scene.background");
}

TEST_CASE("Li: cosine shading is colour times the cosine -d.n") {
    const Scene scene = makeTp1Scene();
    const RayCastIntegrator cosine(Shading::Cosine);
    expectNear("cosine, ray along +z (facing)", cosine.Li(scene, Ray{{0.f, 0.f, 0.f}, {0.f, 0.f, 1.f}}),
               Color(0.f, 0.f, 1.f), 1e-5f, "-d.n = 1 where the ray meets the surface head on");
    // From (0.6, 0, 0) along +z: the hit is (0.6, 0, 2.2), n = (0.6, 0, -0.8), -d.n = 0.8.
    expectNear("cosine, ray from (0.6, 0, 0) along +z", cosine.Li(scene, Ray{{0.6f, 0.f, 0.f}, {0.f, 0.f, 1.f}}),
               Color(0.f, 0.f, 0.8f), 1e-5f,
               "colour * max(-dot(d, n), 0) with the true normal: the dot product is the cosine itself, no gamma");
}

TEST_CASE("Li: the placeholder normal faces the ray") {
    const Scene scene = makeTp1Scene();
    const RayCastIntegrator placeholder(Shading::PlaceholderNormal);
    const float expected = 1.f / std::sqrt(3.f);
    expectNear("placeholder normal, ray along +z", placeholder.Li(scene, Ray{{0.f, 0.f, 0.f}, {0.f, 0.f, 1.f}}),
               Color(0.f, 0.f, expected), 1e-5f,
               "n = normalize(1, 1, 1), turned to -n when d.n > 0; the colour is colour * max(-d.n, 0)");
}

} // TEST_SUITE
