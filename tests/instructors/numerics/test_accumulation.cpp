// The catalogue's pixel averages: a NaN or infinite sample is never averaged away into a plausible
// colour, and 10^7 samples per pixel average to the exact value (the float sum is the foil).
#include "numerics_support.h"

#include "raylab/image_io.h"
#include "raylab/perspective_camera.h"
#include "raylab/renderer.h"

#include <doctest/doctest.h>

#include <atomic>

using namespace raylab;
using namespace raylab::numerics;

namespace {

// Returns `value`, except every `period`-th call, which returns `bad`.
class SometimesBad final : public Integrator {
public:
    SometimesBad(Color value, Color bad, int period) : m_value(value), m_bad(bad), m_period(period) {}
    Color Li(const Scene&, const Ray&) const override { return ++m_calls % m_period == 0 ? m_bad : m_value; }

private:
    Color m_value, m_bad;
    int m_period;
    mutable std::atomic<long long> m_calls{0};
};

} // namespace

TEST_SUITE("numerics") {

TEST_CASE("NaN and infinity in an antialiased average reach the pixel, and the PNG shows them magenta") {
    const Scene scene = makeTp1Scene();
    const PerspectiveCamera camera(12, 8);
    for (const Color bad : {Color(kNaN, 0.f, 0.f), Color(0.f, kInf, 0.f), Color(0.f, 0.f, -kInf)}) {
        const SometimesBad integrator(Color(0.5f), bad, 16); // one bad sample in each pixel's 16
        Renderer renderer(scene, camera, integrator);
        renderer.settings().threads = 1;
        renderer.setNbPixelSamples(16);
        renderer.settings().sampler = SamplerKind::Random;
        const Texture image = renderer.renderImage();
        std::uint64_t nonFinite = 0;
        const Image8 png = quantize(image, &nonFinite);
        CHECK(nonFinite == 12u * 8u);
        CHECK(png.pixel(5, 3)[0] == kNonFiniteRgb[0]);
        CHECK(png.pixel(5, 3)[1] == kNonFiniteRgb[1]);
        CHECK(png.pixel(5, 3)[2] == kNonFiniteRgb[2]);
    }
}

TEST_CASE("10^7 samples per pixel average exactly; a float sum is off by percents") {
    const int n = 10'000'000;
    const Color value(0.3f, 0.7f, 0.1f);
    // The foil: the float sum of the same samples. Past 2^21 its spacing is 0.25, so adding 0.3
    // adds 0.25 or 0.5, never 0.3.
    float naive = 0.f;
    for (int k = 0; k < n; ++k) naive += value.r;
    CHECK(std::abs(naive / float(n) - value.r) / value.r > 0.01f);

    const Scene scene;
    const PerspectiveCamera camera(4, 4);
    const SometimesBad integrator(value, value, 1);
    Renderer renderer(scene, camera, integrator);
    renderer.setNbPixelSamples(n);
    PixelSampler sampler(SamplerKind::Center, n, 0, 1, 2, 4);
    // The sum of 10^7 float samples is exact in double (24 + 24 bits < 53), and so is the mean.
    CHECK(renderer.renderPixel(1, 2, sampler) == value);
}

}
