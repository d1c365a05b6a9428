// Every figure and reference is byte-identical to what the reference solutions drew when these
// hashes were taken: a change to the framework's rendering path (the scene factory, the renderer's
// strategies, the render space, the reference statistics) that moves one 8-bit value, one
// ambiguous pixel or one bit of a converged statistic fails here. A change meant to alter a
// picture updates the table (and `raylab references`) in the same commit. The table holds for the
// C library's single-precision maths it was taken with (glibc 2.36, Debian 12); glibc 2.41 rounds
// them correctly (CORE-MATH), which moves a few 8-bit values: there the cases say so and are skipped.
#include "support/figures.h"

#include "grader/judge/reference_render.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

using namespace raylab;
using namespace raylab::test;

namespace {

// FNV-1a, 64 bits: enough to tell two pictures apart, and written in one line.
class Fnv1a {
public:
    void add(const void* data, std::size_t size) {
        for (std::size_t k = 0; k < size; ++k) m_hash = (m_hash ^ static_cast<const std::uint8_t*>(data)[k]) * 0x100000001b3ull;
    }
    template <typename T> void addAll(const std::vector<T>& values) { add(values.data(), values.size() * sizeof(T)); }
    std::uint64_t value() const { return m_hash; }

private:
    std::uint64_t m_hash = 0xcbf29ce484222325ull;
};

std::uint64_t pixelHash(const Image8& image) {
    Fnv1a h;
    h.addAll(image.rgb);
    return h.value();
}

// The single-precision functions of the C library over 10^4 arguments each, hashed.
std::uint64_t floatMathsHash() {
    Fnv1a h;
    for (int k = 1; k <= 10000; ++k) {
        const float x = float(k) * 1.2345e-4f;
        const float values[] = {std::tan(x),      std::sin(x),  std::cos(x),  std::pow(x, 1.f / 2.2f), std::exp(x),
                                std::log(x),      std::atan(x), std::acos(x), std::asin(x),            std::atan2(x, 1.f - x),
                                std::pow(x, 2.2f)};
        h.add(values, sizeof values);
    }
    return h.value();
}

// Whether this C library's maths are the table's; if not, says the case is skipped (ctest counts it so).
bool tableMathsHere() {
    constexpr std::uint64_t kTableMaths = 0x9f194e4d591ee467ull;
    const std::uint64_t here = floatMathsHash();
    if (here == kTableMaths) return true;
    MESSAGE("skipped: needs the C library's single-precision maths of the table (glibc 2.36's: the hash of its "
            "functions' results " << std::hex << kTableMaths << ", here " << here << ")");
    return false;
}

struct FigureHash {
    const char* id;
    std::uint64_t pixels; // the 8-bit RGB of the figure at its scene file's settings
};

constexpr FigureHash kFigures[] = {
    {"lab1_gradient", 0x1ecb7998ff612b05ull},
    {"lab2_directions", 0x72d376324a7321edull},
    {"lab3_cosine", 0x5b90b3f3bc031aa1ull},
    {"lab3_flat", 0xfbfb877aa11853c9ull},
    {"lab3_placeholder_normal", 0x4826013bfa263500ull},
    {"lab4_a", 0x6bbd485b03b488e1ull},
    {"lab4_b", 0x1a2f4e181016a6a9ull},
    {"lab4_c", 0x3db73efb3ccbd80full},
    {"lab4_d", 0x2b57136af83a5bf8ull},
    {"lab5_antialiased", 0x9c2d2bacac4503cdull},
};

} // namespace

TEST_SUITE("figure hashes") {

TEST_CASE("every figure's 8-bit pixels are the ones in the table") {
    if (!tableMathsHere()) return;
    for (const FigureHash& f : kFigures) {
        CAPTURE(std::string(f.id));
        CHECK(pixelHash(renderFigure(f.id)) == f.pixels);
    }
}

TEST_CASE("adaptive sampling and every sampler draw the same pixels as before") {
    if (!tableMathsHere()) return;
    SceneDescription d = figureScene("lab5_antialiased");
    d.width = 150;
    d.height = 100;
    d.seed = 11;
    d.samples = 4;
    std::uint64_t hashes[std::size(kAllSamplerKinds)] = {};
    for (std::size_t k = 0; k < std::size(kAllSamplerKinds); ++k) {
        d.sampler = kAllSamplerKinds[k];
        d.adaptive = AdaptiveSettings{0.05f, 16, true, SamplerKind::Stratified};
        hashes[k] = pixelHash(renderFigure(d));
    }
    const std::uint64_t expected[] = {
        0xe48072b0f73ff0e9ull, 0x0f346c21085e5735ull, 0x09d8b92b4efbb5b4ull, 0xc50658ba6b09bc85ull,
        0x0324752d36bcadaaull, 0xc9033f6a4e3ac978ull, 0xf6abfdcace1beadeull};
    for (std::size_t k = 0; k < std::size(kAllSamplerKinds); ++k) {
        CAPTURE(samplerName(kAllSamplerKinds[k]));
        CHECK(hashes[k] == expected[k]);
    }
}

TEST_CASE("the references' ambiguous pixels and converged statistics are the ones in the table") {
    if (!tableMathsHere()) return;
    struct Ambiguous {
        const char* id;
        std::vector<std::pair<int, int>> pixels;
    };
    const Ambiguous expected[] = {{"lab2_directions", {}}, {"lab3_cosine", {}}, {"lab4_b", {{552, 159}, {552, 240}}}, {"lab4_d", {{242, 63}, {162, 186}}}};
    for (const Ambiguous& a : expected) {
        CAPTURE(std::string(a.id));
        CHECK(grader::ambiguousPixels(figureScene(a.id), 0) == a.pixels);
    }
    const grader::StatisticalReference s = grader::convergedStatistics(figureScene("lab5_antialiased"), 0);
    Fnv1a h;
    h.addAll(s.mean);
    h.addAll(s.sampleSd);
    CHECK(h.value() == 0x061c8821491ca4cdull);
}

}
