// The image checks' policy (docs/grading.md) on small synthetic images.
#include "grader/judge/compare.h"
#include "grader/judge/diagnosis.h"
#include "src/messages.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>

using namespace raylab;
using namespace raylab::grader;

namespace {

Image8 flat(int w, int h, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    Image8 image{w, h, {}};
    for (int k = 0; k < w * h; ++k) image.rgb.insert(image.rgb.end(), {r, g, b});
    return image;
}

void set(Image8& image, int i, int j, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    std::uint8_t* p = &image.rgb[3 * (std::size_t(j) * image.width + i)];
    p[0] = r;
    p[1] = g;
    p[2] = b;
}

// A random figure's reference: mean 100 LSB everywhere, one sample's sd 16 LSB, 16 samples.
FigureReference statistical(int w, int h) {
    FigureReference f{"noisy", 5, flat(w, h, 100, 100, 100), {}, StatisticalReference{}};
    f.stats->samples = 16;
    f.stats->mean.assign(std::size_t(w) * h * 3, 100.f);
    f.stats->sampleSd.assign(std::size_t(w) * h * 3, 16.f);
    f.stats->worstCorrectRmse = 4.1;
    f.stats->rmseLimit = 1.25 * 4.1;
    return f;
}

// A render of `statistical` with n samples a pixel, whose mean is shifted by `bias` LSB.
Image8 noisyRender(int w, int h, int n, double bias, unsigned seed) {
    std::mt19937 random(seed);
    std::normal_distribution<double> sample(100. + bias, 16. / std::sqrt(double(n)));
    Image8 image{w, h, {}};
    for (int k = 0; k < 3 * w * h; ++k) image.rgb.push_back(std::uint8_t(std::clamp(std::round(sample(random)), 0., 255.)));
    return image;
}

double metric(const ImageVerdict& v, const std::string& name) {
    for (const auto& [n, value] : v.metrics)
        if (n == name) return value;
    FAIL("no metric " << name);
    return 0.;
}

} // namespace

TEST_SUITE("image comparison") {

TEST_CASE("deterministic: 1 LSB passes, 2 LSB fails, ambiguous pixels are excused") {
    FigureReference reference{"d", 3, flat(8, 8, 10, 20, 30), {{5, 5}}, {}};
    Image8 student = flat(8, 8, 11, 19, 30);
    CHECK(compareDeterministic(reference, student).passed);
    set(student, 5, 5, 200, 0, 0); // the ambiguous pixel
    CHECK(compareDeterministic(reference, student).passed);
    set(student, 1, 2, 10, 22, 30);
    const ImageVerdict v = compareDeterministic(reference, student);
    CHECK_FALSE(v.passed);
    CHECK(metric(v, "pixels off by more than 1 LSB") == 1);
    CHECK(metric(v, "largest difference (LSB)") == 2);
    CHECK(v.error[2 * 8 + 1] == 2.f);
}

TEST_CASE("deterministic: one NaN pixel fails and is named") {
    const FigureReference reference{"d", 3, flat(4, 4, 10, 20, 30), {}, {}};
    Image8 student = reference.image;
    set(student, 0, 0, 255, 0, 255);
    const ImageVerdict v = compareDeterministic(reference, student);
    CHECK_FALSE(v.passed);
    CHECK(v.reason.find("NaN") != std::string::npos);
}

TEST_CASE("a wrong size fails before any metric") {
    const FigureReference reference{"d", 3, flat(4, 4, 10, 20, 30), {}, {}};
    const ImageVerdict v = compareImage(reference, flat(4, 3, 10, 20, 30));
    CHECK_FALSE(v.passed);
    CHECK(v.reason == "the image is 4 x 3, the figure is 4 x 4");
}

TEST_CASE("statistical: correct renders pass, whatever the seed") {
    const FigureReference reference = statistical(200, 100);
    for (unsigned seed = 1; seed <= 5; ++seed) {
        const ImageVerdict v = compareStatistical(reference, noisyRender(200, 100, 16, 0., seed));
        CHECK_MESSAGE(v.passed, v.reason);
    }
}

TEST_CASE("statistical: a less noisy (stratified) render passes") {
    const ImageVerdict v = compareStatistical(statistical(200, 100), noisyRender(200, 100, 64, 0., 3));
    CHECK_MESSAGE(v.passed, v.reason);
}

TEST_CASE("statistical: a bias of a quarter LSB fails") {
    const ImageVerdict v = compareStatistical(statistical(200, 100), noisyRender(200, 100, 16, 0.25, 4));
    CHECK_FALSE(v.passed);
    CHECK(v.reason.find("biased") != std::string::npos);
}

TEST_CASE("statistical: a biased render is said biased, not noisy, though its RMSE is over the limit too") {
    const ImageVerdict v = compareStatistical(statistical(200, 100), noisyRender(200, 100, 16, 6., 4));
    CHECK_FALSE(v.passed);
    CHECK(metric(v, "RMSE (LSB)") > metric(v, "allowed RMSE (LSB)"));
    CHECK_MESSAGE(v.reason.find("biased") != std::string::npos, v.reason);
    CHECK_MESSAGE(v.reason.find("noisy") == std::string::npos, v.reason);
}

TEST_CASE("statistical: far fewer samples fail on noise") {
    const ImageVerdict v = compareStatistical(statistical(200, 100), noisyRender(200, 100, 4, 0., 5));
    CHECK_FALSE(v.passed);
    CHECK(v.reason.find("RMSE") != std::string::npos);
}

TEST_CASE("statistical: a few wild pixels are outliers") {
    const FigureReference reference = statistical(200, 100);
    Image8 student = noisyRender(200, 100, 16, 0., 6);
    for (int k = 0; k < 30; ++k) set(student, 7 * k, k, 255, 255, 255);
    const ImageVerdict v = compareStatistical(reference, student);
    CHECK_FALSE(v.passed);
    CHECK(metric(v, "pixels with |z| > 6") >= 30);
}

TEST_CASE("diagnosis: the closest signature is named when it fits, and only then") {
    Mistake dark{"dark", "too dark", "trop sombre", "brighten it", "éclaircissez-la", "", 3, "shade (shade.cpp)", "", "", {{"fig", downsample(flat(16, 16, 10, 10, 10))}}, {}};
    Mistake red{"red", "all red", "toute rouge", "less red", "moins de rouge", "", 3, "shade (shade.cpp)", "", "", {{"fig", downsample(flat(16, 16, 250, 0, 0))}}, {}};
    const std::vector<Mistake> catalogue{dark, red};
    const Image8 reference = flat(16, 16, 100, 100, 100);
    const auto anyMistake = [](const Mistake&) { return true; };
    const Diagnosis d = diagnose(catalogue, "fig", flat(16, 16, 11, 10, 9), reference, anyMistake);
    REQUIRE(d.mistake != nullptr);
    CHECK(d.mistake->id == "dark");
    raylab::setLanguage(raylab::Language::En);
    CHECK(d.text() == "your image matches 'too dark' (lab 3, shade (shade.cpp)): brighten it");
    raylab::setLanguage(raylab::Language::Fr);
    CHECK(d.text() == "votre image correspond à l'erreur «\u00A0trop sombre\u00A0» (TP 3, shade (shade.cpp))\u00A0: éclaircissez-la");
    std::vector<Mistake> labelled{dark}; // numbered in the handouts: M3.4 in English, E3.4 in French
    labelled[0].label = "3.4";
    CHECK(diagnose(labelled, "fig", flat(16, 16, 11, 10, 9), reference, anyMistake).text() ==
          "votre image correspond à l'erreur E3.4 «\u00A0trop sombre\u00A0» (TP 3, shade (shade.cpp))\u00A0: éclaircissez-la");
    raylab::setLanguage(raylab::Language::En);
    CHECK(diagnose(labelled, "fig", flat(16, 16, 11, 10, 9), reference, anyMistake).text() ==
          "your image matches M3.4 'too dark' (lab 3, shade (shade.cpp)): brighten it");
    CHECK(diagnose(catalogue, "fig", flat(16, 16, 60, 60, 60), reference, anyMistake).mistake == nullptr);
    CHECK(diagnose(catalogue, "other", flat(16, 16, 10, 10, 10), reference, anyMistake).mistake == nullptr);
}

TEST_CASE("diagnosis: only the suspects are named") {
    const Image8 reference = flat(16, 16, 100, 100, 100), student = flat(16, 16, 10, 10, 10);
    Mistake own{"own", "dim", "sombre", "brighten it", "éclaircissez-la", "", 4, "lookAt", "", "", {{"fig", downsample(flat(16, 16, 12, 12, 12))}}, {}};
    Mistake earlier{"earlier", "dark", "noire", "brighten it", "éclaircissez-la", "", 2, "camera", "", "", {{"fig", downsample(student)}}, {}};
    const std::vector<Mistake> catalogue{own, earlier};
    const auto ofLabs = [](std::vector<int> labs) {
        return [labs](const Mistake& m) { return std::find(labs.begin(), labs.end(), m.lab) != labs.end(); };
    };
    // Lab 2 is right (or came from the reference): its closer signature is not a candidate.
    const Diagnosis alone = diagnose(catalogue, "fig", student, reference, ofLabs({4}));
    REQUIRE(alone.mistake != nullptr);
    CHECK(alone.mistake->id == "own");
    CHECK(alone.alike == nullptr);
    CHECK(diagnose(catalogue, "fig", student, reference, ofLabs({2, 4})).mistake->id == "earlier");
    CHECK(diagnose(catalogue, "fig", student, reference, ofLabs({})).mistake == nullptr);
}

} // TEST_SUITE
