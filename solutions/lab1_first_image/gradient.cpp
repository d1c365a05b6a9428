// Lab 1: your first image. The reference solution; students write labs/lab1_first_image/gradient.cpp.
#include "gradient.h"

namespace raylab {

namespace {

// k / (n - 1), and 0 when there is a single pixel (no interval to spread over).
float ramp(int k, int n) { return n > 1 ? float(k) / float(n - 1) : 0.f; }

} // namespace

void fillGradient(Texture& texture) {
    for (int j = 0; j < texture.height(); ++j)
        for (int i = 0; i < texture.width(); ++i)
            texture.setPixel(i, j, Color(ramp(i, texture.width()), ramp(j, texture.height()), 0.f));
}

} // namespace raylab
