// raylab references: renders the graded figures from solutions/ into tests/references/, with the
// data the image checks need (docs/grading.md), and the mistakes' signatures.
#include "build_info.h"
#include "commands.h"

#include "grader/compare.h"
#include "grader/diagnosis.h"
#include "grader/references.h"
#include "grader/sandbox.h"

#include "raylab/figure.h"
#include "raylab/gradient.h"
#include "raylab/perspective_camera.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <thread>

namespace raylab::cli {

namespace {

namespace fs = std::filesystem;
using namespace raylab::grader;

// Runs body(j) for every row, on all cores.
void forRows(int height, const std::function<void(int)>& body) {
    const unsigned threads = std::max(1u, std::thread::hardware_concurrency());
    std::vector<std::thread> workers;
    for (unsigned t = 0; t < threads; ++t)
        workers.emplace_back([&, t] {
            for (int j = int(t); j < height; j += int(threads)) body(j);
        });
    for (auto& w : workers) w.join();
}

PerspectiveCamera cameraOf(const SceneDescription& d) {
    const CameraDescription& c = d.camera;
    if (!c.lookAt) return PerspectiveCamera(d.width, d.height, c.fovy);
    return PerspectiveCamera(d.width, d.height, c.position, c.target, c.up, c.fovy);
}

std::unique_ptr<Integrator> integratorOf(Picture picture) {
    switch (picture) {
    case Picture::Directions: return std::make_unique<DirectionIntegrator>();
    case Picture::Flat: return std::make_unique<RayCastIntegrator>(Shading::Flat);
    case Picture::PlaceholderNormal: return std::make_unique<RayCastIntegrator>(Shading::PlaceholderNormal);
    default: return std::make_unique<RayCastIntegrator>(Shading::Cosine);
    }
}

// Pixels whose centre ray is within kAmbiguity pixels of a change of more than 1 LSB: a float
// or double computation of the same formula may land on either side (a centre ray grazing the
// silhouette).
constexpr float kAmbiguity = 2e-3f;

std::vector<std::pair<int, int>> ambiguousPixels(const SceneDescription& d) {
    const PerspectiveCamera camera = cameraOf(d);
    const std::unique_ptr<Integrator> integrator = integratorOf(d.picture);
    const float W = float(d.width), H = float(d.height);
    std::vector<char> flag(std::size_t(d.width) * d.height, 0);
    forRows(d.height, [&](int j) {
        for (int i = 0; i < d.width; ++i) {
            auto at = [&](float dx, float dy) {
                return integrator->Li(d.scene, camera.generateRay((float(i) + 0.5f + dx) / W, (float(j) + 0.5f + dy) / H));
            };
            const Color centre = at(0.f, 0.f);
            for (float dx : {-kAmbiguity, 0.f, kAmbiguity})
                for (float dy : {-kAmbiguity, 0.f, kAmbiguity}) {
                    const Color c = at(dx, dy);
                    for (int k = 0; k < 3; ++k)
                        if (std::abs(int(toByte(c[k])) - int(toByte(centre[k]))) > 1) flag[std::size_t(j) * d.width + i] = 1;
                }
        }
    });
    std::vector<std::pair<int, int>> pixels;
    for (int j = 0; j < d.height; ++j)
        for (int i = 0; i < d.width; ++i)
            if (flag[std::size_t(j) * d.width + i]) pixels.emplace_back(i, j);
    return pixels;
}

// The expected 8-bit value of an N-sample mean that is normal(m, sd^2) in LSB: rounding is not
// unbiased near a constant value (a background of 127.5 LSB is always written 128).
double expectedByte(double m, double sd) {
    if (sd < 1e-3) return std::clamp(std::round(m), 0., 255.);
    auto cdf = [&](double x) { return 0.5 * std::erfc(-(x - m) / (sd * std::sqrt(2.))); };
    double expected = 0.;
    const int low = std::max(0, int(std::floor(m - 8. * sd)) - 1), high = std::min(255, int(std::ceil(m + 8. * sd)) + 1);
    for (int k = low; k <= high; ++k) {
        const double below = k == 0 ? 0. : cdf(k - 0.5), above = k == 255 ? 1. : cdf(k + 0.5);
        expected += k * (above - below);
    }
    return expected;
}

// The converged per-pixel mean and the standard deviation of one uniform sample, in LSB: a grid
// of 4 x 4 points finds the pixels that vary, which then take a 32 x 32 grid.
StatisticalReference convergedStatistics(const SceneDescription& d) {
    const PerspectiveCamera camera = cameraOf(d);
    const std::unique_ptr<Integrator> integrator = integratorOf(d.picture);
    StatisticalReference s;
    s.samples = d.samples;
    s.mean.resize(std::size_t(d.width) * d.height * 3);
    s.sampleSd.resize(s.mean.size());
    // A pixel that the silhouette only grazes can look constant on a coarse grid: a pixel is
    // constant only when its neighbours' centres agree with its own too.
    std::vector<Color> centres(std::size_t(d.width) * d.height);
    forRows(d.height, [&](int j) {
        for (int i = 0; i < d.width; ++i)
            centres[std::size_t(j) * d.width + i] = integrator->Li(
                d.scene, camera.generateRay((float(i) + 0.5f) / float(d.width), (float(j) + 0.5f) / float(d.height)));
    });
    auto neighboursAgree = [&](int i, int j) {
        const Color& c = centres[std::size_t(j) * d.width + i];
        for (int y = std::max(0, j - 1); y <= std::min(d.height - 1, j + 1); ++y)
            for (int x = std::max(0, i - 1); x <= std::min(d.width - 1, i + 1); ++x)
                if (centres[std::size_t(y) * d.width + x] != c) return false;
        return true;
    };
    forRows(d.height, [&](int j) {
        for (int i = 0; i < d.width; ++i) {
            auto grid = [&](int n, glm::dvec3& mean, glm::dvec3& var) {
                glm::dvec3 sum(0.), sumSq(0.);
                for (int b = 0; b < n; ++b)
                    for (int a = 0; a < n; ++a) {
                        const glm::dvec3 c(integrator->Li(
                            d.scene, camera.generateRay((float(i) + (float(a) + 0.5f) / float(n)) / float(d.width),
                                                        (float(j) + (float(b) + 0.5f) / float(n)) / float(d.height))));
                        sum += c;
                        sumSq += c * c;
                    }
                mean = sum / double(n * n);
                var = glm::max(sumSq / double(n * n) - mean * mean, glm::dvec3(0.));
            };
            glm::dvec3 mean, var;
            grid(4, mean, var);
            if (var.x + var.y + var.z > 0. || !neighboursAgree(i, j)) grid(32, mean, var);
            for (int k = 0; k < 3; ++k) {
                const std::size_t index = 3 * (std::size_t(j) * d.width + i) + k;
                s.sampleSd[index] = float(255. * std::sqrt(var[k]));
                s.mean[index] = float(expectedByte(255. * mean[k], s.sampleSd[index] / std::sqrt(double(d.samples))));
            }
        }
    });
    return s;
}

// Renders the figure with 20 seeds: the worst RMSE of a correct render sets the limit. Prints the
// other statistics of those renders too, so the thresholds' margins are seen.
void measureRmseLimit(const SceneDescription& d, FigureReference& f, int threads) {
    double worst = 0., worstBias = 0., worstBiasLimit = 0., worstOutliers = 0.;
    std::vector<Image8> renders;
    SceneDescription seeded = d;
    for (int seed = 1; seed <= 20; ++seed) {
        seeded.seed = std::uint64_t(seed) * 7919u;
        const FigureResult r = renderScene(seeded, RenderOptions{threads, false});
        if (r.status != FigureResult::Status::Rendered) throw std::runtime_error(d.id + ": " + r.message);
        const Image8 image = quantize(*r.image);
        double sumSq = 0.;
        for (std::size_t k = 0; k < image.rgb.size(); ++k) {
            const double e = double(image.rgb[k]) - f.stats->mean[k];
            sumSq += e * e;
        }
        worst = std::max(worst, std::sqrt(sumSq / double(image.rgb.size())));
        renders.push_back(image);
    }
    f.stats->worstCorrectRmse = worst;
    f.stats->rmseLimit = 1.25 * worst;
    for (const Image8& image : renders) {
        const ImageVerdict v = compareStatistical(f, image);
        for (const auto& [name, value] : v.metrics) {
            if (name == "mean signed difference (LSB)") worstBias = std::max(worstBias, std::abs(value));
            if (name == "allowed |mean signed difference| (LSB)") worstBiasLimit = value;
            if (name == "pixels with |z| > 6") worstOutliers = std::max(worstOutliers, value);
        }
    }
    std::printf("  %-24s 20 seeds: worst |mean signed difference| %.4f LSB (allowed %.4f), worst outliers %.0f\n",
                d.id.c_str(), worstBias, worstBiasLimit, worstOutliers);
}

// Each mistake's agent renders the figures; those that fail their check are kept, small.
void makeSignatures(const fs::path& folder, const fs::path& bin, const fs::path& scenes) {
    const ReferenceSet references = loadReferences(folder);
    const std::vector<Mistake> mistakes = loadMistakes(folder);
    for (const Mistake& m : mistakes) {
        const fs::path agent = bin / ("raylab-mistake-" + m.id);
        if (!fs::exists(agent)) {
            std::printf("  %-28s skipped: no %s (build the tests first)\n", m.id.c_str(), agent.string().c_str());
            continue;
        }
        const fs::path scratch = fs::temp_directory_path() / ("raylab-signature-" + m.id);
        fs::remove_all(scratch);
        runAgent(agent, {"--figures", fs::absolute(scenes).string(), "--out", (scratch / "figures").string()}, scratch,
                 SandboxLimits{});
        const fs::path out = folder / "mistakes" / m.id;
        fs::remove_all(out);
        std::string kept;
        for (const FigureReference& r : references.figures) {
            const fs::path png = scratch / "figures" / (r.id + ".png");
            if (!fs::exists(png)) continue;
            const Image8 image = readImage(png);
            if (compareImage(r, image).passed) continue;
            fs::create_directories(out);
            writePng(out / (r.id + ".png"), downsample(image));
            kept += " " + r.id;
        }
        std::printf("  %-28s signatures:%s\n", m.id.c_str(), kept.empty() ? " none (no figure changes)" : kept.c_str());
        fs::remove_all(scratch);
    }
}

int makeReferences(const fs::path& folder, const fs::path& scenes, const std::string& mistakesBin, int threads) {
    std::printf("raylab references: %s -> %s\n", build::kLabOrigins, folder.string().c_str());
    for (const SceneDescription& d : loadSceneFolder(scenes)) {
        const FigureResult r = renderScene(d, RenderOptions{threads, false});
        if (r.status != FigureResult::Status::Rendered)
            throw std::runtime_error(d.id + " does not render from the reference: " + r.message);
        std::uint64_t nonFinite = 0;
        FigureReference f{d.id, d.lab, quantize(*r.image, &nonFinite), {}, {}};
        if (nonFinite) throw std::runtime_error(d.id + ": the reference has NaN pixels");
        if (d.samples > 1 && d.sampler != SamplerKind::Center) {
            f.stats = convergedStatistics(d);
            measureRmseLimit(d, f, threads);
            std::printf("  %-24s statistical: worst RMSE of 20 correct renders %.3f LSB, limit %.3f\n", d.id.c_str(),
                        f.stats->worstCorrectRmse, f.stats->rmseLimit);
        } else {
            if (d.picture != Picture::Gradient) f.ambiguous = ambiguousPixels(d);
            std::printf("  %-24s deterministic: %zu ambiguous pixels\n", d.id.c_str(), f.ambiguous.size());
        }
        writeReference(folder, f);
    }
    if (!mistakesBin.empty()) makeSignatures(folder, mistakesBin, scenes);
    return 0;
}

} // namespace

void addReferencesCommand(CLI::App& app, Context& context) {
    auto out = std::make_shared<std::string>();
    auto mistakes = std::make_shared<std::string>();
    CLI::App* references = app.add_subcommand(
        "references", "instructors: render the reference data of every figure from solutions/ (tests/references)");
    references->add_option("--out", *out, "the reference folder (default: tests/references)");
    references->add_option("--mistakes", *mistakes,
                           "also render the mistakes' signatures with the raylab-mistake-* programs of this folder");
    context.addRenderOptions(references);
    references->callback([&context, out, mistakes] {
        context.impl = "reference";
        if (context.ranInOtherImpl()) return;
        const fs::path folder = out->empty() ? fs::path(build::kSourceDir) / "tests/references" : fs::path(*out);
        context.exitStatus = makeReferences(folder, context.scenes, *mistakes, context.threads);
    });
}

} // namespace raylab::cli
