// Issue 4, item 5: the radius-1 sphere 10^4 away, seen with a narrow fovy, is a clean disc whose
// area matches the analytic one within 0.5%; the textbook formula fills the whole image.
#include "numerics_support.h"

#include "src/figure.h"
#include "raylab/image_io.h"
#include "raylab/perspective_camera.h"

#include <doctest/doctest.h>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

using namespace raylab;
using namespace raylab::numerics;

namespace {

constexpr int kSize = 256;
constexpr double kDistance = 1e4;

// The sphere's silhouette is the cone of half-angle asin(r / D) around the line of sight; on the
// screen at focal 1 it is a circle of radius tan(asin(r / D)). fovy puts that at 80 pixels.
double screenRadius() { return std::tan(std::asin(1. / kDistance)); }
float fovy() { return float(glm::degrees(2. * std::atan(screenRadius() * (kSize / 2.) / 80.))); }

SceneDescription farSphere(const glm::vec3& cameraPosition) {
    SceneDescription d;
    d.width = d.height = kSize;
    d.shading = "flat";
    d.camera.fovy = fovy();
    const glm::dvec3 towards(0.36, 0.48, 0.8);
    const glm::vec3 centre(glm::dvec3(cameraPosition) + kDistance * towards);
    d.camera.lookAt = true;
    d.camera.position = cameraPosition;
    d.camera.target = centre;
    d.scene.add(SphereGeometry(centre, 1.f, Color(0.f, 0.f, 1.f)));
    return d;
}

// The disc's radius in pixels, from the camera's own float screen.
double analyticRadiusPx() {
    const PerspectiveCamera camera(kSize, kSize, fovy());
    return screenRadius() / (double(camera.viewportHeight()) / 2.) * (kSize / 2.);
}

} // namespace

TEST_SUITE("numerics") {

TEST_CASE("the far sphere renders as a clean disc of the analytic area (within 0.5%)") {
    const double radius = analyticRadiusPx();
    CHECK(radius == doctest::Approx(80.).epsilon(1e-4));
    const double area = 3.14159265358979323846 * radius * radius;
    // From the origin, and from 2.3 10^6 away from it (the floating render origin keeps both accurate).
    for (const glm::vec3 position : {glm::vec3(0.f), glm::vec3(1e6f, -2e6f, 5e5f)}) {
        CAPTURE(position.x);
        const FigureResult r = renderScene(farSphere(position), RenderOptions{0, false});
        REQUIRE(r.status == FigureResult::Status::Rendered);
        const Image8 image = quantize(*r.image);
        int disc = 0, stray = 0;
        for (int j = 0; j < kSize; ++j)
            for (int i = 0; i < kSize; ++i) {
                const bool blue = image.pixel(i, j)[2] == 255 && image.pixel(i, j)[0] == 0;
                disc += blue;
                // Clean: blue inside the circle, grey outside, anything else only on the rim.
                const double distance = std::hypot(i + 0.5 - kSize / 2., j + 0.5 - kSize / 2.);
                if (distance < radius - 1.5 || distance > radius + 1.5) stray += blue != (distance < radius);
            }
        CHECK(stray == 0);
        CHECK(std::abs(disc - area) / area < 0.005);
    }
}

TEST_CASE("the far sphere's cosine shading is within one 8-bit level of the long double one, two on the rim") {
    SceneDescription d = farSphere(glm::vec3(0.f));
    d.shading = "cosine";
    const FigureResult r = renderScene(d, RenderOptions{0, false});
    REQUIRE(r.status == FigureResult::Status::Rendered);
    const Image8 image = quantize(*r.image);
    const glm::vec3 centre = d.scene.all<SphereGeometry>()[0].center();
    const PerspectiveCamera camera(kSize, kSize, d.camera.position, d.camera.target, d.camera.up, d.camera.fovy);
    const double radius = analyticRadiusPx();
    int worstInside = 0, worstRim = 0;
    for (int j = 0; j < kSize; ++j)
        for (int i = 0; i < kSize; ++i) {
            const Ray ray = camera.generateRay((float(i) + 0.5f) / kSize, (float(j) + 0.5f) / kSize);
            const study::SphereHit<LD> truth = exact(ray, centre, 1.f);
            if (!truth.hit) continue;
            using V = study::V3<LD>;
            const LD cosine = -study::dot(V::from(ray.direction), study::normalAt(V::from(ray.origin), V::from(ray.direction),
                                                                                  V::from(centre), LD(1), truth.t));
            const int error = std::abs(int(image.pixel(i, j)[2]) - int(std::lround(255. * double(std::max(cosine, LD(0))))));
            // On the outermost half pixel t is ill-conditioned (section 1 of docs/numerics.md).
            const bool rim = std::hypot(i + 0.5 - kSize / 2., j + 0.5 - kSize / 2.) > radius - 0.5;
            int& worst = rim ? worstRim : worstInside;
            worst = std::max(worst, error);
        }
    CHECK(worstInside <= 1);
    CHECK(worstRim <= 2);
}

TEST_CASE("the textbook formula does not give the far sphere's disc") {
    const SceneDescription d = farSphere(glm::vec3(0.f));
    const glm::vec3 centre = d.scene.all<SphereGeometry>()[0].center();
    const PerspectiveCamera camera(kSize, kSize, d.camera.position, d.camera.target, d.camera.up, d.camera.fovy);
    int hits = 0, wrong = 0;
    for (int j = 0; j < kSize; ++j)
        for (int i = 0; i < kSize; ++i) {
            const Ray ray = camera.generateRay((float(i) + 0.5f) / kSize, (float(j) + 0.5f) / kSize);
            const bool foil = textbook(ray, centre, 1.f).hit;
            hits += foil;
            wrong += foil != exact(ray, centre, 1.f).hit;
        }
    const double area = 3.14159265358979323846 * analyticRadiusPx() * analyticRadiusPx();
    CHECK(std::abs(hits - area) / area > 0.005);
    CHECK(wrong > 500); // pixels whose hit/miss differs from the long double truth
    // On the axis of the default camera every pixel "hits": the image is one blue square.
    const PerspectiveCamera axial(kSize, kSize, d.camera.fovy);
    int axialHits = 0;
    for (int j = 0; j < kSize; ++j)
        for (int i = 0; i < kSize; ++i)
            axialHits += textbook(axial.generateRay((float(i) + 0.5f) / kSize, (float(j) + 0.5f) / kSize),
                                  glm::vec3(0.f, 0.f, float(kDistance)), 1.f).hit;
    CHECK(axialHits == kSize * kSize);
}

}
