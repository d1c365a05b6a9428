// Lab 2's function checks: the viewport and the primary rays of known cameras.
#include "checks/check_support.h"

#include "raylab/perspective_camera.h"

#include <cmath>
#include <numbers>

using namespace raylab;
using namespace raylab::checks;

namespace {

// The expected values, from docs/conventions.md, computed here in double.
glm::vec3 expectedDirection(const glm::dvec3& topLeft, double w, double h, const glm::dvec3& u, const glm::dvec3& v,
                            double sx, double sy) {
    return glm::vec3(glm::normalize(topLeft + sx * w * u - sy * h * v));
}

} // namespace

TEST_SUITE("lab2") {

TEST_CASE("updateViewport: the viewport of the default camera") {
    const PerspectiveCamera camera(600, 400, 60.f);
    const double h = 2. * std::tan(30. * std::numbers::pi / 180.);
    expectNear("viewport height, fovy 60", camera.viewportHeight(), float(h), 1e-5f,
               "height = 2 tan(fovy / 2) * focal: fovy is the full angle, in degrees (glm::radians converts)");
    expectNear("viewport width, 600 x 400", camera.viewportWidth(), float(h * 1.5), 1e-5f,
               "width = height * aspect, with aspect = W / H = 1.5");
    expectNear("top-left corner", camera.topLeft(), glm::vec3(float(h * 0.75), float(h * 0.5), 1.f), 1e-5f,
               "topLeft = position - w * focal + v * height / 2 - u * width / 2 (u = (-1, 0, 0) here)");
}

TEST_CASE("updateViewport: fovy is in degrees and halved") {
    const PerspectiveCamera camera(100, 100, 90.f);
    expectNear("viewport height, fovy 90", camera.viewportHeight(), 2.f, 1e-5f,
               "2 tan(90 / 2 degrees) = 2: convert degrees to radians and take half the angle");
}

TEST_CASE("generateRay: the centre and the four corners of the default camera") {
    const PerspectiveCamera camera(600, 400, 60.f);
    const double h = 2. * std::tan(30. * std::numbers::pi / 180.), w = 1.5 * h;
    const glm::dvec3 topLeft(w / 2., h / 2., 1.), u(-1., 0., 0.), v(0., 1., 0.);
    const struct {
        float sx, sy;
        const char* name;
    } points[] = {{0.5f, 0.5f, "centre (0.5, 0.5)"},
                  {0.f, 0.f, "top-left corner (0, 0)"},
                  {1.f, 0.f, "top-right corner (1, 0)"},
                  {0.f, 1.f, "bottom-left corner (0, 1)"},
                  {1.f, 1.f, "bottom-right corner (1, 1)"}};
    for (const auto& p : points) {
        const Ray ray = camera.generateRay(p.sx, p.sy);
        expectNear(std::string("ray origin at the ") + p.name, ray.origin, glm::vec3(0.f), 1e-6f,
                   "a primary ray starts at the camera position");
        expectNear(std::string("ray direction at the ") + p.name, ray.direction,
                   expectedDirection(topLeft, w, h, u, v, p.sx, p.sy), 1e-5f,
                   "direction = normalize(topLeft + sx * width * u - sy * height * v - position): sx goes right "
                   "along u, sy goes down against v");
    }
}

TEST_CASE("generateRay: directions are unit vectors") {
    const PerspectiveCamera camera(640, 480, 75.f);
    for (float sx : {0.f, 0.3f, 1.f})
        for (float sy : {0.f, 0.7f, 1.f}) {
            const float length = glm::length(camera.generateRay(sx, sy).direction);
            if (!expectNear("|direction| at (" + show(sx) + ", " + show(sy) + ")", length, 1.f, 1e-5f,
                            "normalize the direction (glm::normalize): shading and t as a distance rely on it"))
                return;
        }
}

TEST_CASE("generateRay: a camera away from the origin starts its rays at its position") {
    // Needs lab 4's lookAt constructor (the reference one when lab 2 is graded on its own).
    const glm::vec3 position(2.f, 3.f, -4.f);
    const PerspectiveCamera camera(300, 200, position, position + glm::vec3(0.f, 0.f, 1.f), glm::vec3(0.f, 1.f, 0.f), 60.f);
    const Ray ray = camera.generateRay(0.f, 0.f);
    expectNear("ray origin", ray.origin, position, 1e-5f, "the origin of every primary ray is the camera position");
    const double h = 2. * std::tan(30. * std::numbers::pi / 180.), w = 1.5 * h;
    expectNear("direction through the top-left corner", ray.direction,
               expectedDirection({w / 2., h / 2., 1.}, w, h, {-1., 0., 0.}, {0., 1., 0.}, 0., 0.), 1e-5f,
               "topLeft includes the position (topLeft = position - w * focal + ...) and the direction subtracts it");
}

} // TEST_SUITE
