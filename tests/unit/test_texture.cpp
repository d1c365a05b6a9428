#include "raylab/image_io.h"
#include "raylab/texture.h"
#include "support/files.h"

#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <vector>

using namespace raylab;

TEST_SUITE("framework") {

TEST_CASE("a texture stores each pixel at (column i, row j)") {
    Texture t(3, 2);
    CHECK(t.width() == 3);
    CHECK(t.height() == 2);
    CHECK(t.getPixel(2, 1) == Color(0.f));
    t.setPixel(2, 1, Color(0.25f, 0.5f, 1.f));
    t.setPixel(0, 1, Color(1.f, 0.f, 0.f));
    CHECK(t.getPixel(2, 1) == Color(0.25f, 0.5f, 1.f));
    CHECK(t.pixels()[1 * 3 + 2] == Color(0.25f, 0.5f, 1.f)); // row-major
    CHECK(t.pixels()[1 * 3 + 0] == Color(1.f, 0.f, 0.f));
    CHECK(t.getPixel(1, 1) == Color(0.f));
}

TEST_CASE("a texture made from its pixels keeps them in place, and refuses the wrong number") {
    const Texture t(2, 2, {Color(1.f, 0.f, 0.f), Color(0.f, 1.f, 0.f), Color(0.f, 0.f, 1.f), Color(0.5f)});
    CHECK(t.getPixel(1, 0) == Color(0.f, 1.f, 0.f));
    CHECK(t.getPixel(0, 1) == Color(0.f, 0.f, 1.f)); // row-major, as setPixel writes
    CHECK_THROWS_WITH_AS(Texture(3, 2, std::vector<Color>(5)),
                         "Texture: 5 pixels for a 3 x 2 image; it needs width x height", std::invalid_argument);
    CHECK_THROWS_AS(Texture(0, 2, {}), std::invalid_argument);
}

TEST_CASE("a pixel outside the texture is an error that names it") {
    Texture t(600, 400);
    CHECK_THROWS_WITH_AS(t.setPixel(400, 600, Color(1.f)),
                         "Texture: pixel (i=400, j=600) is outside the 600 x 400 image (i is the column, j the row)",
                         std::out_of_range);
    CHECK_THROWS_AS(t.getPixel(-1, 0), std::out_of_range);
    CHECK_THROWS_AS(Texture(0, 5), std::invalid_argument);
}

TEST_CASE("colours are clamped and rounded to the nearest of 256 levels") {
    CHECK(toByte(0.f) == 0);
    CHECK(toByte(1.f) == 255);
    CHECK(toByte(-3.f) == 0);
    CHECK(toByte(7.f) == 255);
    CHECK(toByte(0.5f) == 128);          // 127.5 rounds up
    CHECK(toByte(126.49f / 255.f) == 126);
    CHECK(toByte(126.51f / 255.f) == 127); // truncation would give 126
}

TEST_CASE("a NaN or infinite pixel is written magenta and counted") {
    Texture t(2, 2);
    t.setPixel(0, 0, Color(std::numeric_limits<float>::quiet_NaN(), 0.f, 0.f));
    t.setPixel(1, 1, Color(0.f, std::numeric_limits<float>::infinity(), 0.f));
    t.setPixel(1, 0, Color(0.2f, 0.4f, 0.6f));
    std::uint64_t bad = 0;
    const Image8 image = quantize(t, &bad);
    CHECK(bad == 2);
    CHECK(image.pixel(0, 0)[0] == 255);
    CHECK(image.pixel(0, 0)[1] == 0);
    CHECK(image.pixel(0, 0)[2] == 255);
    CHECK(image.pixel(1, 0)[0] == 51);
    CHECK(image.pixel(1, 0)[1] == 102);
    CHECK(image.pixel(1, 0)[2] == 153);
}

TEST_CASE("a PNG written is read back byte for byte") {
    Texture t(5, 3);
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 5; ++i) t.setPixel(i, j, Color(i / 4.f, j / 2.f, 0.3f));
    const Image8 written = quantize(t);
    const auto file = raylab::test::scratchPath("raylab_test_roundtrip.png");
    writePng(file, written);
    const Image8 read = readImage(file);
    CHECK(read.width == 5);
    CHECK(read.height == 3);
    CHECK(read.rgb == written.rgb);
    std::filesystem::remove(file);
}

TEST_CASE("reading a missing or broken image names the file") {
    CHECK_THROWS_WITH(readImage("no/such/file.png"), "no/such/file.png: no such file");
    const auto file = raylab::test::scratchPath("raylab_test_broken.png");
    { std::ofstream(file) << "not a png"; }
    CHECK_THROWS_WITH(readImage(file), doctest::Contains("not a readable image"));
    std::filesystem::remove(file);
}

}
