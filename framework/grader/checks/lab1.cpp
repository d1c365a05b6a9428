// Lab 1's function checks: the gradient, value by value.
#include "checks/check_support.h"

#include "raylab/gradient.h"

using namespace raylab;
using namespace raylab::checks;

namespace {

// A value may be quantized to 8 bits (by rounding or truncating) before it is stored: a PNG keeps
// no more, so the checks allow one level.
constexpr float kLevel = 1.01f / 255.f;

} // namespace

TEST_SUITE("lab1") {

TEST_CASE("fillGradient: the corners and the middle of a 5 x 3 image") {
    Texture t(5, 3);
    fillGradient(t);
    const char* hint = "red = i / (W - 1) grows to the right (column i), green = j / (H - 1) downwards (row j)";
    expectNear("pixel (0, 0)", t.getPixel(0, 0), Color(0.f, 0.f, 0.f), 1e-6f, hint);
    expectNear("pixel (4, 0), top right", t.getPixel(4, 0), Color(1.f, 0.f, 0.f), 1e-6f, hint);
    expectNear("pixel (0, 2), bottom left", t.getPixel(0, 2), Color(0.f, 1.f, 0.f), 1e-6f, hint);
    expectNear("pixel (4, 2), bottom right", t.getPixel(4, 2), Color(1.f, 1.f, 0.f), 1e-6f, hint);
    expectNear("pixel (1, 1)", t.getPixel(1, 1), Color(0.25f, 0.5f, 0.f), kLevel,
               "divide by W - 1 and H - 1 (not W and H) in floating point, not in integers");
}

TEST_CASE("fillGradient: every pixel is written") {
    Texture t(7, 4);
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 7; ++i) t.setPixel(i, j, Color(-1.f));
    fillGradient(t);
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 7; ++i)
            if (!expectNear("pixel (" + std::to_string(i) + ", " + std::to_string(j) + ")", t.getPixel(i, j),
                            Color(float(i) / 6.f, float(j) / 3.f, 0.f), kLevel,
                            "loop over every column i < W and every row j < H"))
                return;
}

TEST_CASE("fillGradient: a 1-pixel-wide or 1-pixel-high image has no NaN") {
    Texture column(1, 3), row(4, 1);
    fillGradient(column);
    fillGradient(row);
    const char* hint = "W - 1 is 0 for a 1-pixel-wide image: use red = 0 there instead of dividing by 0";
    expectNear("1 x 3 image, pixel (0, 2)", column.getPixel(0, 2), Color(0.f, 1.f, 0.f), 1e-6f, hint);
    expectNear("4 x 1 image, pixel (3, 0)", row.getPixel(3, 0), Color(1.f, 0.f, 0.f), 1e-6f, hint);
}

} // TEST_SUITE
