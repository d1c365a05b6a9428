// The catalogue's camera and image-size cases: parameters without meaning are refused with their
// name and value (the naive camera turns them into NaN or a blank image), and 1 x 1, 1 x N, N x 1
// and very wide images stay exact.
#include "numerics_support.h"

#include "src/figure.h"
#include "gradient.h"
#include "raylab/image_io.h"
#include "raylab/perspective_camera.h"

#include <doctest/doctest.h>
#include <glm/trigonometric.hpp>

#include <cmath>
#include <initializer_list>
#include <stdexcept>
#include <string>

using namespace raylab;
using namespace raylab::numerics;

namespace {

// The foil: the textbook lookAt basis with no checks, and the centre ray of its screen.
glm::vec3 naiveCentreRay(const glm::vec3& position, const glm::vec3& target, const glm::vec3& up) {
    const glm::vec3 w = glm::normalize(position - target);
    const glm::vec3 u = glm::normalize(glm::cross(up, w));
    const glm::vec3 v = glm::cross(w, u);
    return glm::normalize(-w + 0.f * u + 0.f * v);
}

// The checks figure.cpp runs, then the lab 4 constructor.
void makeLookAt(const glm::vec3& position, const glm::vec3& target, const glm::vec3& up, float fovy = 60.f) {
    checkLookAtParameters(position, target, up);
    const PerspectiveCamera camera(60, 40, position, target, up, fovy);
}

} // namespace

TEST_SUITE("numerics") {

TEST_CASE("degenerate lookAt frames: the naive basis is NaN, raylab names the parameter") {
    const glm::vec3 o(0.f), y(0.f, 1.f, 0.f);
    // up parallel to the view direction: cross(up, w) = 0, normalize(0) = NaN.
    CHECK_FALSE(isFinite(naiveCentreRay(o, {0.f, 5.f, 0.f}, y)));
    CHECK_THROWS_WITH_AS(makeLookAt(o, {0.f, 5.f, 0.f}, y), doctest::Contains("up = (0, 1, 0) is parallel to the view direction"),
                         std::invalid_argument);
    CHECK_THROWS_WITH_AS(makeLookAt(o, {0.f, -5.f, 0.f}, {0.f, 2.f, 0.f}), doctest::Contains("parallel"), std::invalid_argument);
    // position equal to the target: w = normalize(0) = NaN.
    CHECK_FALSE(isFinite(naiveCentreRay({1.f, 2.f, 3.f}, {1.f, 2.f, 3.f}, y)));
    CHECK_THROWS_WITH_AS(makeLookAt({1.f, 2.f, 3.f}, {1.f, 2.f, 3.f}, y), doctest::Contains("position = look_at = (1, 2, 3)"),
                         std::invalid_argument);
    // up of zero length.
    CHECK_FALSE(isFinite(naiveCentreRay(o, {0.f, 0.f, 1.f}, glm::vec3(0.f))));
    CHECK_THROWS_WITH_AS(makeLookAt(o, {0.f, 0.f, 1.f}, glm::vec3(0.f)), doctest::Contains("up = (0, 0, 0) has no direction"),
                         std::invalid_argument);
    // NaN and infinite coordinates, each named.
    CHECK_THROWS_WITH_AS(makeLookAt({kNaN, 0.f, 0.f}, {0.f, 0.f, 1.f}, y), doctest::Contains("position = (nan"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(makeLookAt(o, {0.f, kInf, 1.f}, y), doctest::Contains("look_at = (0, inf"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(makeLookAt(o, {0.f, 0.f, 1.f}, {0.f, -kInf, 0.f}), doctest::Contains("up = (0, -inf"), std::invalid_argument);
    // Finite, but position - target overflows: the view direction would be NaN.
    CHECK_THROWS_WITH_AS(makeLookAt({-3e38f, 0.f, 0.f}, {3e38f, 0.f, 0.f}, y), doctest::Contains("look_at - position = (inf, 0, 0) overflows"),
                         std::invalid_argument);
    CHECK_NOTHROW(makeLookAt({1e7f, 1e7f, 1e7f}, {1e7f, 1e7f, 1e7f + 3.f}, y)); // far from the origin is fine
}

TEST_CASE("fovy of 0, 180 or more, negative, NaN or infinite: refused with its value") {
    // The foil: tan(0) = 0 is a screen of no size (every ray the same); tan(90 deg) is about -2.3e7
    // in float, a screen turned inside out.
    CHECK(2.f * std::tan(glm::radians(0.f) / 2.f) == 0.f);
    CHECK(std::abs(2.f * std::tan(glm::radians(180.f) / 2.f)) > 1e7f);
    for (float fovy : {0.f, 180.f, 270.f, -10.f, kNaN, kInf}) {
        CAPTURE(fovy);
        CHECK_THROWS_WITH_AS(PerspectiveCamera(60, 40, fovy), doctest::Contains("fovy = "), std::invalid_argument);
        CHECK_THROWS_AS(makeLookAt({0.f, 0.f, 0.f}, {0.f, 0.f, 1.f}, {0.f, 1.f, 0.f}, fovy), std::invalid_argument);
    }
    // The narrowest and widest meaningful ones still give unit, finite rays; the focal distance is
    // fixed at 1, never 0.
    for (float fovy : {1e-3f, 179.9f}) {
        const PerspectiveCamera camera(60, 40, fovy);
        CHECK(camera.focal() == 1.f);
        for (float s : {0.f, 0.5f, 1.f}) {
            const glm::vec3 d = camera.generateRay(s, s).direction;
            CHECK(isFinite(d));
            CHECK(glm::length(d) == doctest::Approx(1.f).epsilon(1e-6));
        }
    }
}

TEST_CASE("a scene whose camera has no meaning fails to render with the reason, never renders NaN") {
    SceneDescription d;
    d.width = 30;
    d.height = 20;
    d.scene = makeTp1Scene();
    d.camera.lookAt = true;
    d.camera.position = {0.f, 0.f, 0.f};
    d.camera.target = {0.f, 4.f, 0.f};
    const FigureResult r = renderScene(d, RenderOptions{1, false});
    CHECK(r.status == FigureResult::Status::Failed);
    CHECK_FALSE(r.image.has_value());
    CHECK(r.message.find("up = (0, 1, 0) is parallel") != std::string::npos);
}

TEST_CASE("1 x 1, 1 x N and N x 1 images: no W - 1 = 0 division, every pixel finite") {
    // The foil: the gradient's i / (W - 1) is 0 / 0 for a 1-pixel-wide image.
    const int one = 1;
    CHECK(std::isnan(float(0) / float(one - 1)));
    for (auto [w, h] : {std::pair{1, 1}, std::pair{1, 7}, std::pair{7, 1}}) {
        CAPTURE(w);
        CAPTURE(h);
        Texture gradient(w, h);
        fillGradient(gradient);
        std::uint64_t nonFinite = 1;
        (void)quantize(gradient, &nonFinite);
        CHECK(nonFinite == 0);
        CHECK(gradient.getPixel(w - 1, h - 1) == Color(w > 1 ? 1.f : 0.f, h > 1 ? 1.f : 0.f, 0.f));

        SceneDescription d;
        d.width = w;
        d.height = h;
        d.scene = makeTp1Scene();
        d.shading = "cosine";
        const FigureResult r = renderScene(d, RenderOptions{1, false});
        REQUIRE(r.status == FigureResult::Status::Rendered);
        (void)quantize(*r.image, &nonFinite);
        CHECK(nonFinite == 0);
        // The centre pixel of an odd size looks straight down +z, at the sphere's nearest point.
        CHECK(r.image->getPixel(w / 2, h / 2) == Color(0.f, 0.f, 1.f));
    }
}

TEST_CASE("very wide images: pixel centres within 1/32 pixel up to 2^20, refused beyond") {
    // The renderer computes sx = (i + 0.5) / W in float: a relative error of 2^-24, so W 2^-25 pixels.
    for (int width : {16384, 16383, 100003, (1 << 20) - 3}) {
        CAPTURE(width);
        double worst = 0.;
        for (int i = 0; i < width; i += 1 + width / 100000)
            worst = std::max(worst, std::abs(double((float(i) + 0.5f) / float(width)) * width - (i + 0.5)));
        CHECK(worst <= 1. / 32.);
    }
    // The foil: at 2^24 columns, i + 0.5 rounds to an even integer and neighbours share one centre.
    const float w24 = float(1 << 24);
    CHECK((float((1 << 24) - 3) + 0.5f) / w24 == (float((1 << 24) - 2) + 0.5f) / w24);
    CHECK_NOTHROW(PerspectiveCamera(1 << 20, 1));
    CHECK_THROWS_WITH_AS(PerspectiveCamera((1 << 20) + 1, 1), doctest::Contains("1048577 x 1"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(PerspectiveCamera(4, 1 << 21), doctest::Contains("above 1048576"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(PerspectiveCamera(0, 5), doctest::Contains("0 x 5"), std::invalid_argument);
}

}
