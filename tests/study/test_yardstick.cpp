// The yardstick of `raylab bench` draws the reference labs' image of lab 5's scene bit for bit, so
// that the bench compares the same work (docs/performance.md).
#include "support/scene_files.h"
#include "yardstick.h"

#include "src/figure.h"

#include <doctest/doctest.h>

#include <cstring>

using namespace raylab;

TEST_SUITE("yardstick") {

TEST_CASE("the yardstick's pixels are the reference labs' bytes at 1, 4 and 64 samples") {
    SceneDescription d = loadSceneFile(raylab::test::figureSceneFile("lab5_antialiased"));
    d.width = 48; // small, but the sphere's edge still crosses many pixels
    d.height = 32;
    for (int samples : {1, 4, 64}) {
        CAPTURE(samples);
        d.samples = samples;
        const FigureResult raylab = renderScene(d, RenderOptions{});
        REQUIRE(raylab.status == FigureResult::Status::Rendered);
        const std::vector<Color>& expected = raylab.image->pixels();
        const std::vector<Color> hand = study::renderYardstick(d);
        REQUIRE(hand.size() == expected.size());
        CHECK(std::memcmp(hand.data(), expected.data(), hand.size() * sizeof(Color)) == 0);
    }
}

TEST_CASE("the yardstick refuses a scene it does not draw") {
    SceneDescription d = loadSceneFile(raylab::test::figureSceneFile("lab5_antialiased"));
    d.sampler = SamplerKind::Stratified;
    CHECK_THROWS_AS(study::renderYardstick(d), std::invalid_argument);
}

}
