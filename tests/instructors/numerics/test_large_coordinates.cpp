// The catalogue's large world coordinates: a camera 10^7 from the origin renders the image it renders
// at the origin, because raylab renders around a floating origin; the world-space normal is the foil.
#include "numerics_support.h"

#include "src/figure.h"
#include "raylab/image_io.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cstdlib>
#include <initializer_list>

using namespace raylab;
using namespace raylab::numerics;

namespace {

SceneDescription sphereSeenFrom(const glm::vec3& position) {
    SceneDescription d;
    d.width = 60;
    d.height = 40;
    d.shading = "cosine";
    d.camera.lookAt = true;
    d.camera.position = position;
    d.camera.target = position + glm::vec3(0.f, 0.f, 1.f);
    d.scene.add(SphereGeometry(position + glm::vec3(0.f, 0.f, 3.f), 1.f, Color(0.f, 0.f, 1.f)));
    return d;
}

// The largest angle between the lab code's normal at its hit point and the exact one, over rays
// from `origin` towards a radius-1 sphere at `centre`.
double worstNormalError(const glm::vec3& origin, const glm::vec3& centre) {
    double worst = 0.;
    const SphereGeometry sphere(centre, 1.f, Color(1.f));
    for (int k = 0; k < 400; ++k) {
        const glm::vec3 aim(0.95f * std::cos(0.1f * float(k)) * float(k) / 400.f, 0.95f * std::sin(0.1f * float(k)) * float(k) / 400.f, 3.f);
        const Ray ray{origin, glm::normalize(aim)};
        HitRecord hit;
        REQUIRE(sphere.intersect(ray, 0.f, kInf, hit));
        const study::SphereHit<LD> truth = exact(ray, centre, 1.f);
        REQUIRE(truth.hit);
        const glm::dvec3 exactNormal = glm::dvec3(ray.origin) + double(truth.t) * glm::dvec3(ray.direction) - glm::dvec3(centre);
        worst = std::max(worst, angle(glm::dvec3(sphere.computeNormal(hit.position)), exactNormal));
    }
    return worst;
}

} // namespace

TEST_SUITE("numerics") {

TEST_CASE("large world coordinates: 10^4 ... 10^7 from the origin, the image seen from the origin") {
    const FigureResult atOrigin = renderScene(sphereSeenFrom(glm::vec3(0.f)), RenderOptions{1, false});
    REQUIRE(atOrigin.status == FigureResult::Status::Rendered);
    const Image8 expected = quantize(*atOrigin.image);
    for (float offset : {1e4f, 1e5f, 1e6f, 1e7f}) {
        CAPTURE(offset);
        const FigureResult far = renderScene(sphereSeenFrom(glm::vec3(offset, -offset, offset)), RenderOptions{1, false});
        REQUIRE(far.status == FigureResult::Status::Rendered);
        const Image8 image = quantize(*far.image);
        int worst = 0;
        for (std::size_t k = 0; k < image.rgb.size(); ++k) worst = std::max(worst, std::abs(image.rgb[k] - expected.rgb[k]));
        CHECK(worst <= 1); // one 8-bit level: the render space keeps 6e-5 of precision near the camera
    }
    // A camera within 512 of the world origin renders in world coordinates, untouched.
    CHECK(RenderSpace({511.f, -300.f, 2.f}).origin() == glm::vec3(0.f));
    CHECK(RenderSpace({1e7f, -1e4f, 600.f}).origin() == glm::vec3(10000384.f, -10240.f, 1024.f));
}

TEST_CASE("large world coordinates: normals from world-space hit points are off, render-space ones are not") {
    const glm::vec3 camera(1e7f, 0.f, 0.f), centre = camera + glm::vec3(0.f, 0.f, 3.f);
    // The foil: o + t d rounded to float's spacing of 1 at 10^7, then (p - c) / r.
    CHECK(worstNormalError(camera, centre) > 0.05);
    // What the renderer hands the lab code: the same rays and sphere in the camera's render space.
    const RenderSpace space(camera);
    Scene world;
    world.setAll(std::vector<SphereGeometry>{SphereGeometry(centre, 1.f, Color(1.f))});
    const Scene moved = space.toRender(world);
    CHECK(moved.all<SphereGeometry>()[0].center() == space.toRender(camera) + glm::vec3(0.f, 0.f, 3.f));
    CHECK(worstNormalError(space.toRender(camera), moved.all<SphereGeometry>()[0].center()) < 1e-4);
}

}
