// The reference figures show what the table of figures says (README, docs/conventions.md).
#include "support/figures.h"

#include "src/parallel.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numbers>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

using namespace raylab;
using namespace raylab::test;

namespace {

// Pixels whose centre lies inside the circle of radius r (pixels) around the image centre: the
// count a one-sample render of a centred sphere must reach. Centres within `margin` of the
// circle are ambiguous at float precision and returned apart.
struct DiscCount {
    int inside = 0;
    int ambiguous = 0;
};

DiscCount pixelCentresInDisc(int width, int height, double r, double margin = 1e-3) {
    DiscCount c;
    for (int j = 0; j < height; ++j)
        for (int i = 0; i < width; ++i) {
            const double d = std::hypot(i + 0.5 - width / 2., j + 0.5 - height / 2.);
            if (std::abs(d - r) < margin) ++c.ambiguous;
            else if (d < r) ++c.inside;
        }
    return c;
}

void checkCentredDisc(const Image8& image, double radiusPx) {
    const Coverage sphere = coverageOf(image, 128, 128, 128);
    const DiscCount expected = pixelCentresInDisc(image.width, image.height, radiusPx);
    CHECK(sphere.count >= expected.inside);
    CHECK(sphere.count <= expected.inside + expected.ambiguous);
    CHECK(sphere.x == doctest::Approx(300.).epsilon(1e-9));
    CHECK(sphere.y == doctest::Approx(200.).epsilon(1e-9));
}

} // namespace

TEST_SUITE("figures") {

TEST_CASE("lab1_gradient: red grows to the right, green downwards, exactly") {
    const Image8 image = renderFigure("lab1_gradient");
    CHECK(pixelIs(image, 0, 0, 0, 0, 0));
    CHECK(pixelIs(image, 599, 0, 255, 0, 0));
    CHECK(pixelIs(image, 0, 399, 0, 255, 0));
    CHECK(pixelIs(image, 599, 399, 255, 255, 0));
    CHECK(pixelIs(image, 299, 133, int(std::lround(255. * 299 / 599)), int(std::lround(255. * 133 / 399)), 0));
}

TEST_CASE("lab1_gradient: a 1-pixel-wide or -high image uses 0 there") {
    SceneDescription d = figureScene("lab1_gradient");
    d.width = 1;
    d.height = 5;
    Image8 image = renderFigure(d);
    CHECK(pixelIs(image, 0, 0, 0, 0, 0));
    CHECK(pixelIs(image, 0, 4, 0, 255, 0));
    d.width = 1;
    d.height = 1;
    image = renderFigure(d);
    CHECK(pixelIs(image, 0, 0, 0, 0, 0));
}

TEST_CASE("lab2_directions: (d + 1) / 2, the centre looking along +z and +x on the left") {
    const Image8 image = renderFigure("lab2_directions");
    // Pixel (300, 200)'s centre is half a pixel right and below the screen centre: d ~ (0, 0, 1).
    const std::uint8_t* centre = image.pixel(300, 200);
    CHECK(std::abs(centre[0] - 128) <= 1);
    CHECK(std::abs(centre[1] - 128) <= 1);
    CHECK(centre[2] == 255);
    CHECK(image.pixel(0, 200)[0] > 128);   // left: +x (u = (-1, 0, 0) points right)
    CHECK(image.pixel(599, 200)[0] < 128);
    CHECK(image.pixel(300, 0)[1] > 128);   // top: +y
    CHECK(image.pixel(300, 399)[1] < 128);
}

TEST_CASE("lab3_flat: the silhouette is a disc of radius 122.47 px") {
    // The sphere (radius 1 at distance 3) subtends asin(1/3); on the screen at focal 1 its
    // silhouette has radius tan(asin(1/3)) = 1 / sqrt(8), and 400 px span 2 tan(30 degrees).
    const double radiusPx = (1. / std::sqrt(8.)) * 400. / (2. * std::tan(std::numbers::pi / 6.));
    CHECK(radiusPx == doctest::Approx(122.47).epsilon(1e-4));
    const Image8 image = renderFigure("lab3_flat");
    checkCentredDisc(image, radiusPx);
    CHECK(pixelIs(image, 300, 200, 0, 0, 255));
    CHECK(pixelIs(image, 0, 0, 128, 128, 128));
}

TEST_CASE("lab3_cosine: the same disc, brightest at the centre, dark at the rim") {
    const Image8 image = renderFigure("lab3_cosine");
    checkCentredDisc(image, (1. / std::sqrt(8.)) * 400. / (2. * std::tan(std::numbers::pi / 6.)));
    CHECK(pixelIs(image, 300, 200, 0, 0, 255));
    CHECK(image.pixel(300 + 121, 200)[2] < 100);
    const Image8 placeholder = renderFigure("lab3_placeholder_normal");
    CHECK(coverageOf(placeholder, 128, 128, 128).count == coverageOf(image, 128, 128, 128).count);
}

TEST_CASE("lab4_a: from (0, 0, -2), the sphere is a centred disc of radius 70.71 px") {
    const double radiusPx = (1. / std::sqrt(24.)) * 400. / (2. * std::tan(std::numbers::pi / 6.));
    CHECK(radiusPx == doctest::Approx(70.71).epsilon(1e-4));
    checkCentredDisc(renderFigure("lab4_a"), radiusPx);
}

TEST_CASE("lab4_b, c, d: the sphere is right of centre, below, upper left") {
    const Coverage b = coverageOf(renderFigure("lab4_b"), 128, 128, 128);
    CHECK(b.x > 300. + 50.);
    CHECK(b.y == doctest::Approx(200.).epsilon(1e-9));
    const Coverage c = coverageOf(renderFigure("lab4_c"), 128, 128, 128);
    CHECK(c.y > 200. + 50.);
    CHECK(c.x == doctest::Approx(300.).epsilon(1e-9));
    const Coverage d = coverageOf(renderFigure("lab4_d"), 128, 128, 128);
    CHECK(d.x < 300. - 50.);
    CHECK(d.y < 200. - 50.);
}

TEST_CASE("lab5_antialiased: averaged samples soften the silhouette, not the interior") {
    const Image8 aliased = renderFigure("lab3_cosine");
    const Image8 smooth = renderFigure("lab5_antialiased");
    CHECK(pixelIs(smooth, 0, 0, 128, 128, 128));
    int inBetween = 0; // silhouette pixels mixing background and sphere
    for (int j = 0; j < 400; ++j)
        for (int i = 0; i < 600; ++i) {
            const std::uint8_t* p = smooth.pixel(i, j);
            if (p[0] > 0 && p[0] < 128) ++inBetween;
        }
    CHECK(inBetween > 500); // about the 770 px of the perimeter
    CHECK(std::abs(int(smooth.pixel(300, 200)[2]) - int(aliased.pixel(300, 200)[2])) <= 1);
}

TEST_CASE("the same scene and seed give the same image with any number of threads") {
    SceneDescription d = figureScene("lab5_antialiased");
    d.samples = 4;
    const Image8 one = renderFigure(d, 1);
    CHECK(renderFigure(d, 2).rgb == one.rgb);
    CHECK(renderFigure(d, 3).rgb == one.rgb);
    d.sampler = SamplerKind::Stratified;
    CHECK(renderFigure(d, 1).rgb == renderFigure(d, 4).rgb);
    d.sampler = SamplerKind::Random;
    d.seed = 2;
    CHECK(renderFigure(d, 2).rgb != one.rgb);
}

}

TEST_SUITE("figures") {

TEST_CASE("SceneRender: a far lookAt camera and its scene are moved into the camera's render space") {
    SceneDescription d = figureScene("lab4_a");
    const glm::vec3 far(1e7f, -3000.f, 700.f);
    d.camera.position = far;
    d.camera.target = far + glm::vec3(0.f, 0.f, 1.f);
    d.scene.setAll(std::vector<SphereGeometry>{SphereGeometry(far + glm::vec3(0.f, 0.f, 3.f), 1.f, Color(1.f))});
    d.scene.setAll(std::vector<Plane>{Plane(far + glm::vec3(0.f, -1.f, 0.f), glm::vec3(0.f, 1.f, 0.f), Color(1.f))});
    d.scene.lights = {PointLight{far + glm::vec3(0.f, 4.f, 0.f), Color(10.f)}};
    const SceneRender render(d);
    CHECK(render.space().origin() == glm::vec3(10000384.f, -3072.f, 1024.f));
    CHECK(render.camera().position() == glm::vec3(-384.f, 72.f, -324.f));
    CHECK(render.scene().all<SphereGeometry>()[0].center() == render.camera().position() + glm::vec3(0.f, 0.f, 3.f));
    CHECK(render.scene().all<Plane>()[0].point() == render.camera().position() + glm::vec3(0.f, -1.f, 0.f));
    CHECK(render.scene().all<Plane>()[0].normal() == glm::vec3(0.f, 1.f, 0.f));
    CHECK(render.scene().lights[0].position == render.camera().position() + glm::vec3(0.f, 4.f, 0.f));
    CHECK(render.scene().lights[0].intensity == Color(10.f));
}

TEST_CASE("SceneRender: the default camera renders in world space, with the scene file's sampling") {
    const SceneDescription d = figureScene("lab5_antialiased");
    SceneRender render(d, RenderOptions{2, false});
    CHECK(render.space().origin() == glm::vec3(0.f));
    CHECK(render.scene().all<SphereGeometry>()[0].center() == d.scene.all<SphereGeometry>()[0].center());
    CHECK(render.renderer().nbPixelSamples() == d.samples);
    CHECK(render.renderer().settings().sampler == d.sampler);
    CHECK_THROWS_AS(SceneRender(figureScene("lab1_gradient")), std::invalid_argument);
}

}

TEST_SUITE("framework") {

TEST_CASE("parallelFor runs every item once, on at most the threads asked for, and rethrows the first error") {
    for (int threads : {0, 1, 3}) {
        CAPTURE(threads);
        std::vector<std::atomic<int>> runs(100);
        std::atomic<unsigned> highestWorker{0};
        parallelFor(runs.size(), threads, false, [&](std::size_t item, unsigned worker) {
            ++runs[item];
            for (unsigned seen = highestWorker; worker > seen && !highestWorker.compare_exchange_weak(seen, worker);) {}
        });
        CHECK(std::all_of(runs.begin(), runs.end(), [](const std::atomic<int>& n) { return n == 1; }));
        CHECK(highestWorker < workerCount(threads, runs.size()));
    }
    CHECK(workerCount(8, 3) == 3);
    CHECK(workerCount(2, 0) == 1);
    std::atomic<int> started{0};
    CHECK_THROWS_WITH_AS(parallelFor(1000, 2, false,
                                     [&](std::size_t item, unsigned) {
                                         ++started;
                                         if (item == 5) throw std::runtime_error("item 5");
                                         std::this_thread::sleep_for(std::chrono::milliseconds(1));
                                     }),
                         "item 5", std::runtime_error);
    CHECK(started < 100); // no new item starts after the error: each thread ends the one it has
}

}
