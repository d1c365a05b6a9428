// The camera conventions of docs/conventions.md, checked on the reference solution of labs 2 and 4.
#include "raylab/perspective_camera.h"

#include <doctest/doctest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <initializer_list>
#include <limits>
#include <numbers>
#include <stdexcept>

using namespace raylab;

namespace {

constexpr float kEps = 1e-6f;

bool near(const glm::vec3& a, const glm::vec3& b, float eps = kEps) { return glm::length(a - b) <= eps; }

} // namespace

TEST_SUITE("camera") {

TEST_CASE("the default camera has the lookAt frame of (0,0,0) -> (0,0,1), up (0,1,0)") {
    const PerspectiveCamera camera(600, 400);
    CHECK(camera.position() == glm::vec3(0.f));
    CHECK(camera.u() == glm::vec3(-1.f, 0.f, 0.f));
    CHECK(camera.v() == glm::vec3(0.f, 1.f, 0.f));
    CHECK(camera.w() == glm::vec3(0.f, 0.f, -1.f));
    CHECK(camera.fovy() == 60.f);
    CHECK(camera.focal() == 1.f);
    // The lookAt constructor builds the very same frame.
    const PerspectiveCamera lookAt(600, 400, {0.f, 0.f, 0.f}, {0.f, 0.f, 1.f}, {0.f, 1.f, 0.f}, 60.f);
    CHECK(near(lookAt.u(), camera.u()));
    CHECK(near(lookAt.v(), camera.v()));
    CHECK(near(lookAt.w(), camera.w()));
}

TEST_CASE("the viewport is 2 tan(fovy / 2) high and aspect times as wide") {
    const PerspectiveCamera camera(600, 400, 60.f);
    const float height = 2.f * std::tan(std::numbers::pi_v<float> / 6.f);
    CHECK(camera.viewportHeight() == doctest::Approx(height).epsilon(1e-6));
    CHECK(camera.viewportWidth() == doctest::Approx(height * 1.5f).epsilon(1e-6));
    // top-left = position - w + v h/2 - u w/2: x positive (u points to -x), y up, z = 1.
    CHECK(near(camera.topLeft(), glm::vec3(height * 0.75f, height * 0.5f, 1.f)));
}

TEST_CASE("(0, 0) is the top-left corner of the screen, (1, 1) the bottom-right one") {
    const PerspectiveCamera camera(600, 400, 90.f); // screen half-height 1, half-width 1.5
    const Ray centre = camera.generateRay(0.5f, 0.5f);
    CHECK(centre.origin == glm::vec3(0.f));
    CHECK(near(centre.direction, glm::vec3(0.f, 0.f, 1.f)));
    CHECK(near(camera.generateRay(0.f, 0.f).direction, glm::normalize(glm::vec3(1.5f, 1.f, 1.f))));
    CHECK(near(camera.generateRay(1.f, 0.f).direction, glm::normalize(glm::vec3(-1.5f, 1.f, 1.f))));
    CHECK(near(camera.generateRay(0.f, 1.f).direction, glm::normalize(glm::vec3(1.5f, -1.f, 1.f))));
    CHECK(near(camera.generateRay(1.f, 1.f).direction, glm::normalize(glm::vec3(-1.5f, -1.f, 1.f))));
    for (float s : {0.f, 0.3f, 1.f}) CHECK(glm::length(camera.generateRay(s, 1.f - s).direction) == doctest::Approx(1.f));
}

TEST_CASE("pixel centres: the ray of pixel (i, j) goes through ((i + 0.5) / W, (j + 0.5) / H)") {
    // A 2 x 2 image with fovy 90: the four pixel centres sit at (+-0.5, +-0.5) on the screen at z = 1.
    const PerspectiveCamera camera(2, 2, 90.f);
    CHECK(near(camera.generateRay(0.25f, 0.25f).direction, glm::normalize(glm::vec3(0.5f, 0.5f, 1.f))));
    CHECK(near(camera.generateRay(0.75f, 0.75f).direction, glm::normalize(glm::vec3(-0.5f, -0.5f, 1.f))));
}

TEST_CASE("the lookAt frame is right-handed and orthonormal, looking along -w") {
    const glm::vec3 position(4.f, -1.f, 0.f), target(-1.f, -1.f, 2.f);
    const PerspectiveCamera camera(600, 400, position, target, {0.f, 1.f, 0.f}, 60.f);
    CHECK(near(camera.w(), glm::normalize(position - target)));
    CHECK(near(camera.u(), glm::normalize(glm::cross(glm::vec3(0.f, 1.f, 0.f), camera.w()))));
    CHECK(near(glm::cross(camera.u(), camera.v()), camera.w()));
    CHECK(glm::dot(camera.u(), camera.v()) == doctest::Approx(0.f).epsilon(kEps));
    CHECK(glm::length(camera.v()) == doctest::Approx(1.f));
    CHECK(near(camera.generateRay(0.5f, 0.5f).direction, -camera.w()));
    CHECK(camera.generateRay(0.5f, 0.5f).origin == position);
    CHECK(camera.v().y > 0.f); // up stays up
}

TEST_CASE("camera parameters without meaning are refused with their name and value") {
    CHECK_THROWS_WITH_AS(PerspectiveCamera(600, 400, 0.f), doctest::Contains("camera: fovy = 0 degrees has no meaning"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(PerspectiveCamera(600, 400, 180.f), doctest::Contains("strictly between 0 and 180"), std::invalid_argument);
    CHECK_THROWS_AS(PerspectiveCamera(600, 400, std::numeric_limits<float>::quiet_NaN()), std::invalid_argument);
    CHECK_THROWS_WITH_AS(PerspectiveCamera(0, 400), doctest::Contains("0 x 400"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(checkLookAtParameters({1.f, 2.f, 3.f}, {1.f, 2.f, 3.f}, {0.f, 1.f, 0.f}),
                         doctest::Contains("looks nowhere"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(checkLookAtParameters({0.f, 0.f, 0.f}, {0.f, 5.f, 0.f}, {0.f, 1.f, 0.f}),
                         doctest::Contains("parallel to the view direction"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(checkLookAtParameters({0.f, 0.f, 0.f}, {0.f, 0.f, 1.f}, {0.f, 0.f, 0.f}),
                         doctest::Contains("up = (0, 0, 0)"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(checkLookAtParameters({0.f, std::numeric_limits<float>::infinity(), 0.f}, {0.f, 0.f, 1.f}, {0.f, 1.f, 0.f}),
                         doctest::Contains("position"), std::invalid_argument);
    CHECK_NOTHROW(checkLookAtParameters({0.f, 0.f, 0.f}, {0.f, 0.f, 1.f}, {0.f, 1.f, 0.f}));
}

}
