// Lab 1's function checks: the gradient, value by value, on the handout's sizes and on sizes drawn
// at grading time.
#include "grader/judge/checks/checks.h"
#include "probes.h"

#include "src/messages.h"

#include <cmath>
#include <functional>
#include <utility>

namespace raylab::grader {

namespace {

// A value may be quantized to 8 bits (by rounding or truncating) before it is stored: a PNG keeps
// no more, so the checks allow one level.
constexpr double kLevel = 1.01 / 255.;

// The texture a call returned, W x H, row by row.
struct Gradient {
    int width, height;
    std::vector<glm::dvec3> pixels;
    // Whether it holds W x H pixels, as the judging that reads them needs: another count is the
    // student's answer, wrong.
    bool expectSize(Judge& judge) const {
        const std::size_t count = std::size_t(width) * std::size_t(height);
        const std::string what = tr("what.lab1.pixel_count", {{"width", std::to_string(width)}, {"height", std::to_string(height)}});
        return judge.expectTrue(what, pixels.size() == count, std::to_string(count), std::to_string(pixels.size()),
                                tr("hint.lab1.pixel_count"));
    }
    glm::dvec3 pixel(int i, int j) const { return pixels[std::size_t(j) * std::size_t(width) + std::size_t(i)]; }
    glm::dvec3 expected(int i, int j) const {
        return {width > 1 ? double(i) / (width - 1) : 0., height > 1 ? double(j) / (height - 1) : 0., 0.};
    }
    std::string name(int i, int j) const {
        return tr("what.lab1.image_pixel", {{"width", std::to_string(width)},
                                            {"height", std::to_string(height)},
                                            {"pixel", tr("what.lab1.pixel", {{"i", std::to_string(i)}, {"j", std::to_string(j)}})}});
    }
    // The hint a wrong pixel earns: the cause its value shows, never one the code does not have (a
    // flipped ramp is not a pixel left unwritten, nor a division by zero).
    std::string hint(int i, int j) const {
        const glm::dvec3 p = pixel(i, j);
        if (p == glm::dvec3(-1.)) return tr("hint.lab1.every_pixel"); // the probe's mark: never written
        const bool flat = width == 1 || height == 1;
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z) ||
            (width == 1 && p.x != 0.) || (height == 1 && p.y != 0.))
            return tr(flat ? "hint.lab1.one_pixel" : "hint.lab1.float_division");
        return tr("hint.lab1.ramp");
    }
    bool expectPixel(Judge& judge, int i, int j, double tolerance) const {
        return judge.expectNear(name(i, j), pixel(i, j), expected(i, j), tolerance, hint(i, j));
    }
};

struct Size {
    int width, height;
};

// A fillGradient check: one call a size, the handout's then those drawn at grading time; `judge`
// receives the textures in that order, once each holds its W x H pixels.
FunctionCheck gradientCheck(std::string name, std::vector<Size> sizes,
                            std::function<void(const std::vector<Gradient>& textures, Judge& judge)> judge) {
    std::vector<protocol::Call> calls;
    for (const Size& s : sizes) calls.push_back(probes::fillGradient(s.width, s.height));
    return {std::move(name), std::move(calls), [sizes, judge](const auto& out, Judge& j) {
                std::vector<Gradient> textures;
                for (std::size_t k = 0; k < sizes.size(); ++k)
                    textures.push_back({sizes[k].width, sizes[k].height, probes::fillGradient.answer(out[k])});
                bool sized = true;
                for (const Gradient& g : textures) sized = g.expectSize(j) && sized;
                if (sized) judge(textures, j);
            }};
}

void addChecks(LabChecks& checks, CaseRandom& random) {
    // Drawn sizes never equal the fixed ones: an answer learnt by heart for those fails these.
    const int width = random.integer(6, 40), height = random.integer(4, 30);
    checks.add(gradientCheck(
        "corners_and_middle", {{5, 3}, {width, height}},
        [](const std::vector<Gradient>& textures, Judge& judge) {
            const Gradient& fixed = textures[0];
            auto pixel = [](int i, int j) { return tr("what.lab1.pixel", {{"i", std::to_string(i)}, {"j", std::to_string(j)}}); };
            judge.expectNear(pixel(0, 0), fixed.pixel(0, 0), {0., 0., 0.}, 1e-6, fixed.hint(0, 0));
            judge.expectNear(tr("what.lab1.top_right", {{"pixel", pixel(4, 0)}}), fixed.pixel(4, 0), {1., 0., 0.}, 1e-6, fixed.hint(4, 0));
            judge.expectNear(tr("what.lab1.bottom_left", {{"pixel", pixel(0, 2)}}), fixed.pixel(0, 2), {0., 1., 0.}, 1e-6, fixed.hint(0, 2));
            judge.expectNear(tr("what.lab1.bottom_right", {{"pixel", pixel(4, 2)}}), fixed.pixel(4, 2), {1., 1., 0.}, 1e-6, fixed.hint(4, 2));
            // The corners right and the middle wrong: 1 / 4 and 1 / 2 lost to an integer division.
            const bool cornersRight = judge.passed();
            judge.expectNear(pixel(1, 1), fixed.pixel(1, 1), {0.25, 0.5, 0.}, kLevel,
                      cornersRight ? tr("hint.lab1.float_division") : fixed.hint(1, 1));
            const Gradient& drawn = textures[1];
            const int w = drawn.width, h = drawn.height;
            for (const auto& [i, j] : {std::pair{0, 0}, {w - 1, 0}, {0, h - 1}, {w - 1, h - 1}, {w / 2, h / 2}})
         drawn.expectPixel(judge, i, j, kLevel);
        }));

    const int otherWidth = random.integer(8, 40), otherHeight = random.integer(5, 30);
    checks.add(gradientCheck("every_pixel", {{7, 4}, {otherWidth, otherHeight}},
                            [](const std::vector<Gradient>& textures, Judge& judge) {
                                for (const Gradient& g : textures)
                                    for (int j = 0; j < g.height; ++j)
                                        for (int i = 0; i < g.width; ++i)
                                            if (!g.expectPixel(judge, i, j, kLevel)) return;
                            }));

    const int tall = random.integer(4, 20), wide = random.integer(5, 20);
    checks.add(gradientCheck("one_pixel_wide",
                            {{1, 3}, {4, 1}, {1, tall}, {wide, 1}},
                            [](const std::vector<Gradient>& textures, Judge& judge) {
                                for (const Gradient& g : textures) g.expectPixel(judge, g.width - 1, g.height - 1, 1e-6);
                            }));
}

} // namespace

RAYLAB_REGISTER_CHECKS(addChecks);

} // namespace raylab::grader
