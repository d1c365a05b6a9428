// `raylab study antialiasing --quick`'s code path: the files it writes and what its numbers must show.
#include "antialiasing_study.h"
#include "culled_render.h"

#include "src/figure.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>
#include <string>

using namespace raylab;
using namespace raylab::study;

namespace {

const AntialiasingResult& quickStudy() {
    static const AntialiasingResult result = [] {
        AntialiasingOptions o;
        o.scene = std::filesystem::path(RAYLAB_SOURCE_DIR) / "labs/lab5_antialiasing/scenes/lab5_antialiased.toml";
        o.thinObjects = std::filesystem::path(RAYLAB_SOURCE_DIR) / "scenes/study/adaptive_thin_objects.toml";
        o.out = std::filesystem::path(RAYLAB_BINARY_DIR) / "study-quick";
        o.quick = true;
        o.print = false;
        return runAntialiasingStudy(o);
    }();
    return result;
}

std::map<std::string, std::vector<const StudyRow*>> bySampler() {
    std::map<std::string, std::vector<const StudyRow*>> m;
    for (const StudyRow& r : quickStudy().rows)
        if (!r.adaptive) m[r.sampler].push_back(&r);
    return m;
}

std::string read(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

} // namespace

TEST_SUITE("antialiasing study") {

TEST_CASE("the exact reference: a pixel's average, checked against its own refinement and simple cases") {
    CentredSphere s;
    s.width = 60;
    s.height = 40;
    const ExactImage coarse = exactCentredSphere(s, 16), fine = exactCentredSphere(s, 48);
    double worst = 0., covered = 0.;
    for (std::size_t p = 0; p < coarse.pixels.size(); ++p) {
        worst = std::max(worst, std::abs(coarse.pixels[p].b - fine.pixels[p].b));
        covered += coarse.coverage[p];
    }
    CHECK(worst < 1e-6);
    // The disc's area in pixels: pi r^2, r = tan(asin(1/3)) = 1 / sqrt(8) screen units, 40 px for 2 tan(30 degrees).
    const double r = (1. / std::sqrt(8.)) * 40. / (2. * std::tan(std::numbers::pi / 6.));
    CHECK(covered == doctest::Approx(std::numbers::pi * r * r).epsilon(1e-9));
    CHECK(coarse.pixels[0] == glm::dvec3(0.5)); // a corner sees the background only
    // The centre pixel: fully covered, blue, as bright as the cosine near the axis.
    const glm::dvec3 centre = coarse.pixels[20 * 60 + 30];
    CHECK(centre.r == 0.);
    CHECK(centre.b < 1.);
    CHECK(centre.b > 0.995); // cos = sqrt((1 - 8 rho^2) / (1 + rho^2)), rho < 0.04 in this pixel
    s.cosine = false;
    const ExactImage flat = exactCentredSphere(s);
    for (std::size_t p = 0; p < flat.pixels.size(); ++p) CHECK(flat.pixels[p].r == doctest::Approx(0.5 * (1. - flat.coverage[p])));
}

TEST_CASE("log-log slopes and where a series reaches a target") {
    CHECK(logLogSlope({1, 4, 16}, {1, 0.5, 0.25}) == doctest::Approx(-0.5));
    CHECK(whereReaches({1, 4, 16}, {1, 0.5, 0.25}, 0.5) == doctest::Approx(4.));
    CHECK(*whereReaches({1, 4, 16}, {1, 0.5, 0.25}, 0.3535534) == doctest::Approx(8.).epsilon(1e-6));
    CHECK_FALSE(whereReaches({1, 4}, {1, 0.5}, 0.1).has_value());
}

TEST_CASE("the quick study writes its CSV, plots and Markdown") {
    const AntialiasingResult& r = quickStudy();
    const auto out = std::filesystem::path(RAYLAB_BINARY_DIR) / "study-quick";
    const std::string csv = read(out / "accuracy.csv");
    CHECK(csv.rfind("sampler,setting,samples,seconds,runs,rmse,silhouette_rmse,psnr,max_error,refined_fraction\n", 0) == 0);
    CHECK(std::count(csv.begin(), csv.end(), '\n') == std::ptrdiff_t(r.rows.size() + 1));
    CHECK(r.rows.size() == kStudySamplers.size() * 5 + 6); // 1..256 samples; six adaptive settings
    for (const char* svg : {"accuracy_samples.svg", "accuracy_time.svg"}) {
        const std::string text = read(out / svg);
        CHECK(text.rfind("<svg", 0) == 0);
        CHECK(text.find("</svg>") != std::string::npos);
        CHECK(text.find("stratified (slope -") != std::string::npos); // the time slope depends on the machine
    }
    const std::string md = read(out / "accuracy.md");
    CHECK(md.find("accuracy_samples.svg") != std::string::npos);
    CHECK(md.find("## The failure case") != std::string::npos);
    CHECK(r.referenceCheck < 1e-6);
}

TEST_CASE("errors fall as samples grow, at the rates theory gives on silhouette pixels") {
    const auto series = bySampler();
    for (const std::string& name : kStudySamplers) {
        INFO(name);
        const auto& rows = series.at(name);
        REQUIRE(rows.size() == 5);
        for (std::size_t k = 1; k < rows.size(); ++k) {
            CHECK(rows[k]->error.silhouetteRmse < rows[k - 1]->error.silhouetteRmse);
            CHECK(rows[k]->error.rmse < rows[k - 1]->error.rmse);
            CHECK(rows[k]->error.maxError <= rows[k - 1]->error.maxError * 1.5);
        }
        std::vector<double> x, y;
        for (std::size_t k = 1; k < rows.size(); ++k) x.push_back(rows[k]->samples), y.push_back(rows[k]->error.silhouetteRmse);
        const double slope = logLogSlope(x, y);
        MESSAGE(name, ": slope on silhouette pixels ", slope);
        // 196 silhouette pixels: the fitted slope is known to about +-0.1.
        if (name == "random") CHECK(std::abs(slope + 0.5) < 0.12);
        else CHECK(std::abs(slope + 0.75) < 0.12);
    }
}

TEST_CASE("adaptive sampling reaches stratified 256's error with fewer samples; its failure case shows") {
    const StudyRow* uniform = nullptr;
    for (const StudyRow& r : quickStudy().rows)
        if (r.sampler == "stratified" && r.samples == 256.) uniform = &r;
    REQUIRE(uniform != nullptr);
    bool reached = false;
    for (const StudyRow& r : quickStudy().rows)
        if (r.adaptive && r.adaptive->baseSamples == 16 && r.adaptive->widen) {
            CHECK(r.samples < 0.5 * uniform->samples);
            reached = reached || r.error.rmse <= 1.1 * uniform->error.rmse;
        }
    CHECK(reached);
    const auto& f = quickStudy().failure;
    REQUIRE(f.size() == 4); // 16 widen, 16 no-widen, 4 widen, 4 no-widen
    CHECK(f[0].inkFound > 0.85);
    CHECK(f[0].inkFound > f[1].inkFound);
    CHECK(f[2].objectsMissed > f[0].objectsMissed + 3);
    CHECK(f[3].inkFound < 0.75);
}

// The study's thin-objects reference is rendered tile by tile, each tile asking only the spheres
// its rays can meet: the image must be the renderer's, bit for bit, spheres across tile borders included.
TEST_CASE("a culled render draws the renderer's image, bit for bit") {
    SceneDescription d = loadSceneFile(std::filesystem::path(RAYLAB_SOURCE_DIR) / "scenes/study/adaptive_thin_objects.toml");
    d.samples = 16;
    {
        // Spheres a few pixels across, on corners of the 16-pixel tiles and just beside their edges: a
        // tile must keep a sphere whose centre is in its neighbour.
        const SceneRender probe(d);
        const float w = float(d.width), h = float(d.height);
        for (const auto& [x, y] : std::vector<std::pair<float, float>>{{16.f, 16.f}, {17.f, 40.f}, {30.5f, 47.f}, {47.f, 15.f}, {100.f, 65.2f}}) {
            const Ray ray = probe.camera().generateRay(x / w, y / h);
            d.scene.add(SphereGeometry(ray.origin + 3.f * ray.direction, 0.1f, Color(1.f, 0.2f, 0.2f)));
        }
    }
    for (SamplerKind kind : {SamplerKind::Stratified, SamplerKind::Random}) {
        d.sampler = kind;
        const Texture culled = renderCulled(d, 2);
        const FigureResult whole = renderScene(d, RenderOptions{2, false});
        REQUIRE((whole.status == FigureResult::Status::Rendered && whole.image));
        int differing = 0, inked = 0;
        for (int j = 0; j < d.height; ++j)
            for (int i = 0; i < d.width; ++i) {
                differing += culled.getPixel(i, j) != whole.image->getPixel(i, j);
                inked += whole.image->getPixel(i, j) != d.scene.background;
            }
        CHECK(differing == 0);
        CHECK(inked > 40); // the spheres are there, to be culled wrongly
    }
    d.sampler = SamplerKind::Adaptive;
    CHECK_THROWS_AS(renderCulled(d, 2), std::invalid_argument);
}

}
