// Scene::intersect over spheres and planes, Scene::occluded (the shadow test), and the shadow rays
// a render counts: none in a scene without lights.
#include "raylab/integrator_registry.h"
#include "raylab/perspective_camera.h"
#include "raylab/renderer.h"
#include "raylab/scene.h"

#include <doctest/doctest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <limits>
#include <numbers>

using namespace raylab;

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

// The unit sphere at (0, 0, 3) above the ground y = -1.
Scene sphereOnGround() {
    Scene scene = makeTp1Scene();
    scene.add(Plane(glm::vec3(0.f, -1.f, 0.f), glm::vec3(0.f, 1.f, 0.f), Color(0.5f)));
    return scene;
}

} // namespace

TEST_SUITE("shadow rays") {

TEST_CASE("intersect finds the nearest object, sphere or plane, and the hit refers to it as a Shape") {
    const Scene scene = sphereOnGround();
    HitRecord hit;
    REQUIRE(scene.intersect(Ray{{0.f, 0.f, 0.f}, {0.f, 0.f, 1.f}}, hit));
    CHECK(hit.object == &scene.all<SphereGeometry>()[0]);
    CHECK(hit.t == 2.f);
    CHECK(hit.object->computeNormal(hit.position) == glm::vec3(0.f, 0.f, -1.f)); // the sphere's own normal
    CHECK(hit.object->color() == Color(0.f, 0.f, 1.f));
    REQUIRE(scene.intersect(Ray{{0.f, 3.f, 3.f}, {0.f, -1.f, 0.f}}, hit)); // down onto the sphere's top
    CHECK(hit.object == &scene.all<SphereGeometry>()[0]);
    CHECK(hit.t == 2.f);
    REQUIRE(scene.intersect(Ray{{0.f, 3.f, 0.f}, {0.f, -1.f, 0.f}}, hit)); // beside it, onto the ground
    CHECK(hit.object == &scene.all<Plane>()[0]);
    CHECK(hit.t == 4.f);
    CHECK(hit.object->computeNormal(hit.position) == glm::vec3(0.f, 1.f, 0.f));
    CHECK(hit.object->color() == Color(0.5f));
    // A sphere below the ground, seen from above: the ground hides it.
    Scene buried = sphereOnGround();
    buried.add(SphereGeometry(glm::vec3(0.f, -5.f, 0.f), 1.f, Color(1.f)));
    REQUIRE(buried.intersect(Ray{{0.f, 3.f, 0.f}, {0.f, -1.f, 0.f}}, hit));
    CHECK(hit.object == &buried.all<Plane>()[0]);
}

TEST_CASE("occluded: an object strictly between tMin and tMax, the light's own point excluded") {
    const Scene scene = sphereOnGround();
    // From the point where the sphere touches the ground (t = 0) up through the sphere to its top
    // (t = 2), towards a light above it: the sphere is in between.
    const Ray up{{0.f, -1.f, 3.f}, {0.f, 1.f, 0.f}};
    CHECK(scene.occluded(up, 1e-4f, 10.f));
    CHECK_FALSE(scene.occluded(up, 1e-4f, 1.f)); // a light inside the sphere: its top is beyond it
    // tMax exactly at the sphere's top: the interval is open, the light's own point does not block.
    CHECK_FALSE(scene.occluded(up, 1e-4f, 2.f));
    CHECK(scene.occluded(up, 1e-4f, std::nextafter(2.f, 3.f)));
    CHECK_FALSE(scene.occluded(up, 0.f, 1.f)); // tMin = 0 leaves out the point the ray leaves (t = 0)...
    CHECK(scene.occluded(up, -1.f, 1.f));      // ...which a tMin below 0 takes in
    // tMin exactly at the ground the ray leaves (t = 0): the ground does not shadow itself.
    const Ray fromGround{{5.f, -1.f, 0.f}, {0.f, 1.f, 0.f}};
    CHECK_FALSE(scene.occluded(fromGround, 0.f, 10.f));
    // A plane exactly at tMax (the light in the plane) does not block; just before it does.
    const Ray down{{5.f, 3.f, 0.f}, {0.f, -1.f, 0.f}};
    CHECK_FALSE(scene.occluded(down, 0.f, 4.f));
    CHECK(scene.occluded(down, 0.f, std::nextafter(4.f, 5.f)));
    // An occluder beyond the light casts no shadow.
    CHECK_FALSE(scene.occluded(Ray{{0.f, 0.f, 0.f}, {0.f, 0.f, 1.f}}, 1e-4f, 1.5f));
    CHECK(scene.occluded(Ray{{0.f, 0.f, 0.f}, {0.f, 0.f, 1.f}}, 1e-4f, 2.5f));
}

TEST_CASE("occluded: grazing rays, and a scene without objects") {
    const Scene scene = sphereOnGround();
    // Tangent to the sphere at (1, 0, 3): it touches it.
    CHECK(scene.occluded(Ray{{1.f, 0.f, 0.f}, {0.f, 0.f, 1.f}}, 1e-4f, 10.f));
    CHECK_FALSE(scene.occluded(Ray{{1.001f, 0.f, 0.f}, {0.f, 0.f, 1.f}}, 1e-4f, 10.f));
    // Along the ground, in its plane: a plane has no thickness, it does not block.
    CHECK_FALSE(scene.occluded(Ray{{5.f, -1.f, 0.f}, {0.f, 0.f, 1.f}}, 1e-4f, 10.f));
    // Just above the ground and parallel to it.
    CHECK_FALSE(scene.occluded(Ray{{5.f, -0.999f, 0.f}, {0.f, 0.f, 1.f}}, 1e-4f, kInf));
    // A NaN ray is not blocked by anything; nor is any ray in an empty scene, nor an empty interval.
    CHECK_FALSE(scene.occluded(Ray{{0.f, std::nanf(""), 0.f}, {0.f, 0.f, 1.f}}, 1e-4f, 10.f));
    CHECK_FALSE(Scene{}.occluded(Ray{{0.f, 0.f, 0.f}, {0.f, 0.f, 1.f}}, 0.f, kInf));
    CHECK_FALSE(scene.occluded(Ray{{0.f, 0.f, 0.f}, {0.f, 0.f, 1.f}}, 3.f, 3.f));
}

TEST_CASE("a scene without lights traces no shadow ray; with one, one per hit that faces it") {
    // The camera looks straight at a wall filling the whole picture, facing it.
    Scene wall;
    wall.add(Plane(glm::vec3(0.f, 0.f, 5.f), glm::vec3(0.f, 0.f, -1.f), Color(1.f)));
    const PerspectiveCamera camera(40, 30);
    const auto lambert = makeRegisteredIntegrator("lambert", {{"ambient", 0.25f}});
    Renderer renderer(wall, camera, *lambert);
    renderer.settings().threads = 2;
    const Texture dark = renderer.renderImage();
    CHECK(renderer.stats().primaryRays == 1200);
    CHECK(renderer.stats().shadowRays == 0);
    CHECK(dark.getPixel(20, 15) == Color(0.25f)); // the ambient term alone

    wall.lights.push_back(PointLight{glm::vec3(0.f, 0.f, 0.f), Color(100.f)});
    const Texture lit = renderer.renderImage();
    CHECK(renderer.stats().shadowRays == 1200); // every pixel sees the wall, lit from the front
    // The wall's centre: 1 / pi * 100 * cos 0 / 5^2 more than the ambient term.
    CHECK(lit.getPixel(20, 15).r == doctest::Approx(0.25 + 100. / (std::numbers::pi * 25.)).epsilon(2e-3));

    // Lit from behind: no shadow ray is needed (the cosine is not positive).
    wall.lights[0].position = glm::vec3(0.f, 0.f, 10.f);
    renderer.renderImage();
    CHECK(renderer.stats().shadowRays == 0);
}

TEST_CASE("the reference Lambert shading: a shadowed point gets the ambient term alone") {
    Scene scene = sphereOnGround();
    scene.lights.push_back(PointLight{glm::vec3(0.f, 5.f, 3.f), Color(50.f)});
    const auto lambert = makeRegisteredIntegrator("lambert", {{"ambient", 0.1f}});
    // The ground near the sphere is in its shadow; far beside it, it is lit.
    // (1.1, -1, 3), seen from beside the sphere: its shadow on the ground has a radius of 6 / sqrt(24) = 1.22.
    const Color shadowed = lambert->Li(scene, Ray{{5.f, 3.f, 3.f}, glm::normalize(glm::vec3(-3.9f, -4.f, 0.f))});
    const Color lit = lambert->Li(scene, Ray{{6.f, 3.f, 3.f}, {0.f, -1.f, 0.f}});
    CHECK(shadowed == Color(0.05f)); // ambient 0.1 * the ground's 0.5
    // 0.05 + 0.5 / pi * 50 * cos / r^2, with the light at (0, 5, 3) seen from (6, -1, 3): r^2 = 72, cos = 6 / sqrt 72.
    CHECK(lit.r == doctest::Approx(0.05 + 0.5 / std::numbers::pi * 50. * (6. / std::sqrt(72.)) / 72.).epsilon(1e-4));
}

} // TEST_SUITE
