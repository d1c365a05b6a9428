#include "antialiasing_study.h"

#include "culled_render.h"
#include "src/svg_plot.h"

#include "src/atomic_file.h"
#include "src/figure.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace raylab::study {

namespace {

struct Job {
    SamplerKind kind = SamplerKind::Random;
    int samples = 1;
    AdaptiveSettings adaptive;
};

struct Rendered {
    Texture image{1, 1};
    RenderStats stats;
    double seconds = 0.; // median
    int runs = 0;
};

Rendered render(const SceneDescription& scene, const Job& job, int runs, int threads) {
    SceneDescription d = scene;
    d.sampler = job.kind;
    d.samples = job.samples;
    d.adaptive = job.adaptive;
    SceneRender setup(d, RenderOptions{threads, false});
    Renderer& renderer = setup.renderer();
    Rendered r;
    std::vector<double> seconds;
    for (int k = 0; k < runs; ++k) {
        Texture image = renderer.renderImage(); // deterministic: every run gives the same picture
        seconds.push_back(renderer.stats().seconds);
        if (k == 0) r.image = std::move(image);
    }
    std::sort(seconds.begin(), seconds.end());
    r.seconds = seconds[seconds.size() / 2];
    r.runs = runs;
    r.stats = renderer.stats();
    return r;
}

CentredSphere centredSphere(const SceneDescription& d) {
    const std::vector<SphereGeometry>& spheres = d.scene.all<SphereGeometry>();
    const bool fits = !d.camera.lookAt && d.scene.objectCount() == 1 && spheres.size() == 1 && spheres[0].center().x == 0.f &&
                      spheres[0].center().y == 0.f && spheres[0].center().z > spheres[0].radius() &&
                      (d.shading == "cosine" || d.shading == "flat");
    if (!fits)
        throw std::runtime_error(d.file.string() + ": the exact reference needs one sphere on the default camera's axis "
                                 "(center [0, 0, z]), shaded flat or cosine");
    const SphereGeometry& s = spheres[0];
    return CentredSphere{d.width, d.height, d.camera.fovy, s.center().z, s.radius(), s.color(), d.scene.background,
                         d.shading == "cosine"};
}

std::string fmt(const char* format, double v) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, format, v);
    return buffer;
}

// The samples (or seconds) a sampler needs for an error `target`: interpolated between measured
// points, else extrapolated along the slope of its last three points (marked "~").
std::string reach(const std::vector<double>& x, const std::vector<double>& y, double target, const char* format) {
    if (auto v = whereReaches(x, y, target)) return fmt(format, *v);
    if (x.size() < 3) return "-";
    const std::vector<double> lx(x.end() - 3, x.end()), ly(y.end() - 3, y.end());
    const double slope = logLogSlope(lx, ly);
    if (!(slope < 0.)) return "never";
    std::string extrapolated = fmt(format, x.back() * std::pow(target / y.back(), 1. / slope));
    extrapolated.insert(extrapolated.begin(), '~');
    return extrapolated;
}

struct SamplerSeries {
    std::vector<double> samples, seconds, rmse, silhouette;
};

std::map<std::string, SamplerSeries> seriesOf(const std::vector<StudyRow>& rows) {
    std::map<std::string, SamplerSeries> m;
    for (const StudyRow& r : rows) {
        if (r.adaptive) continue;
        SamplerSeries& s = m[r.sampler];
        s.samples.push_back(r.samples);
        s.seconds.push_back(r.seconds);
        s.rmse.push_back(r.error.rmse);
        s.silhouette.push_back(r.error.silhouetteRmse);
    }
    return m;
}

// The slope fitted from 4 samples on: a single sample is not yet in the asymptotic regime.
double fittedSlope(const std::vector<double>& x, const std::vector<double>& y) {
    std::vector<double> fx, fy;
    for (std::size_t k = 0; k < x.size(); ++k)
        if (x[k] >= 4.) fx.push_back(x[k]), fy.push_back(y[k]);
    return logLogSlope(fx, fy);
}

void writeCsv(const std::filesystem::path& file, const std::vector<StudyRow>& rows) {
    std::ostringstream out;
    out << "sampler,setting,samples,seconds,runs,rmse,silhouette_rmse,psnr,max_error,refined_fraction\n";
    for (const StudyRow& r : rows)
        out << r.sampler << ',' << settingName(r) << ',' << r.samples << ',' << r.seconds << ',' << r.runs << ','
            << r.error.rmse << ',' << r.error.silhouetteRmse << ',' << r.error.psnr << ',' << r.error.maxError << ','
            << r.refinedFraction << '\n';
    writeFileAtomically(file, out.str());
}

void writePlots(const std::filesystem::path& out, const AntialiasingResult& result) {
    const auto series = seriesOf(result.rows);
    LogLogPlot samples{"Silhouette pixels: RMSE against samples per pixel", "samples per pixel (mean for adaptive)",
                       "RMSE on silhouette pixels", {}};
    LogLogPlot time{"Whole image: RMSE against render time", "seconds (median)", "RMSE over the image", {}};
    for (const std::string& name : kStudySamplers) {
        const auto it = series.find(name);
        if (it == series.end()) continue;
        const SamplerSeries& s = it->second;
        samples.series.push_back({name + " (slope " + fmt("%.2f", fittedSlope(s.samples, s.silhouette)) + ")", s.samples, s.silhouette});
        time.series.push_back({name + " (slope " + fmt("%.2f", logLogSlope(s.seconds, s.rmse)) + ")", s.seconds, s.rmse});
    }
    Series adaptiveSamples{"adaptive 16+256, thresholds", {}, {}, false}, adaptiveTime = adaptiveSamples;
    for (const StudyRow& r : result.rows)
        if (r.adaptive && r.adaptive->baseSamples == 16) {
            adaptiveSamples.x.push_back(r.samples);
            adaptiveSamples.y.push_back(r.error.silhouetteRmse);
            adaptiveTime.x.push_back(r.seconds);
            adaptiveTime.y.push_back(r.error.rmse);
        }
    samples.series.push_back(adaptiveSamples);
    time.series.push_back(adaptiveTime);
    writeFileAtomically(out / "accuracy_samples.svg", toSvg(samples));
    writeFileAtomically(out / "accuracy_time.svg", toSvg(time));
}

std::vector<StudyRow> measureUniform(const SceneDescription& d, const ExactImage& exact, const AntialiasingOptions& o,
                                     const std::vector<int>& counts) {
    std::vector<StudyRow> rows;
    for (const std::string& name : kStudySamplers)
        for (int n : counts) {
            const Job job{*samplerKindFromString(name), n, {}};
            const int runs = o.quick ? 1 : (n >= 1024 ? 1 : o.repeats);
            const Rendered r = render(d, job, runs, o.threads);
            rows.push_back({name, std::nullopt, double(n), r.seconds, r.runs, compare(r.image, exact), 0.});
            if (o.print)
                std::printf("  %-10s %5d spp %9.4f s  rmse %.3e  silhouette %.3e\n", name.c_str(), n, r.seconds,
                            rows.back().error.rmse, rows.back().error.silhouetteRmse);
            std::fflush(stdout);
        }
    return rows;
}

AdaptiveSettings rendererSettings(const AdaptiveStudySetting& s) {
    return AdaptiveSettings{s.threshold, kAdaptiveMaxSamples, s.widen, SamplerKind::Stratified};
}

std::vector<StudyRow> measureAdaptive(const SceneDescription& d, const ExactImage& exact, const AntialiasingOptions& o) {
    std::vector<AdaptiveStudySetting> settings;
    for (float t : {0.3f, 0.1f, 0.03f, 0.01f}) settings.push_back({16, t, true});
    settings.push_back({16, 0.1f, false});
    settings.push_back({4, 0.1f, true});
    std::vector<StudyRow> rows;
    const double pixels = double(d.width) * d.height;
    for (const AdaptiveStudySetting& s : settings) {
        const Rendered r = render(d, Job{SamplerKind::Adaptive, s.baseSamples, rendererSettings(s)}, o.quick ? 1 : o.repeats, o.threads);
        rows.push_back({"adaptive", s, double(r.stats.primaryRays) / pixels, r.seconds, r.runs, compare(r.image, exact),
                        double(r.stats.refinedPixels) / pixels});
        if (o.print)
            std::printf("  adaptive %-22s %7.1f spp %8.4f s  rmse %.3e  silhouette %.3e  refined %.2f%%\n",
                        settingName(rows.back()).c_str(), rows.back().samples, r.seconds, rows.back().error.rmse,
                        rows.back().error.silhouetteRmse, 100. * rows.back().refinedFraction);
    }
    return rows;
}

// How far a pixel's colour is from the background: the "ink" of what covers it.
double inkAt(const Texture& t, const Color& background, int i, int j) {
    const Color c = t.getPixel(i, j) - background;
    return double(std::abs(c.r) + std::abs(c.g) + std::abs(c.b));
}

double totalInk(const Texture& t, const Color& background) {
    double ink = 0.;
    for (int j = 0; j < t.height(); ++j)
        for (int i = 0; i < t.width(); ++i) ink += inkAt(t, background, i, j);
    return ink;
}

// The pixel each sphere's centre projects to, on the default camera (whose right is -x).
std::vector<std::pair<int, int>> projectedCentres(const SceneDescription& d) {
    const double vh = 2. * std::tan(d.camera.fovy * std::numbers::pi / 360.), vw = vh * d.width / d.height;
    std::vector<std::pair<int, int>> centres;
    for (const SphereGeometry& s : d.scene.all<SphereGeometry>())
        centres.push_back({int((-s.center().x / s.center().z / vw + 0.5) * d.width),
                           int((0.5 - s.center().y / s.center().z / vh) * d.height)});
    return centres;
}

// The small objects of which no pixel around their centre shows any ink.
int objectsMissed(const Texture& t, const Color& background, const std::vector<std::pair<int, int>>& centres) {
    int missed = 0;
    for (auto [ci, cj] : centres) {
        double seen = 0.;
        for (int j = std::max(0, cj - 1); j <= std::min(t.height() - 1, cj + 1); ++j)
            for (int i = std::max(0, ci - 1); i <= std::min(t.width() - 1, ci + 1); ++i) seen += inkAt(t, background, i, j);
        missed += seen == 0.;
    }
    return missed;
}

// Adaptive sampling on objects smaller than a pixel, against a stratified render with many samples.
std::vector<FailureRow> measureFailure(const AntialiasingOptions& o) {
    const SceneDescription d = loadSceneFile(o.thinObjects);
    SceneDescription stratified = d;
    stratified.sampler = SamplerKind::Stratified;
    stratified.samples = o.quick ? 1024 : 4096;
    // 24 spheres, most pixels near none of them: each tile asks only the spheres it can see.
    const Texture reference = renderCulled(stratified, o.threads);
    const Color bg = d.scene.background;
    const std::vector<std::pair<int, int>> centres = projectedCentres(d);
    const double referenceInk = totalInk(reference, bg);

    std::vector<FailureRow> rows;
    for (int base : {16, 4})
        for (bool widen : {true, false}) {
            const AdaptiveStudySetting setting{base, 0.05f, widen};
            const Rendered r = render(d, Job{SamplerKind::Adaptive, base, rendererSettings(setting)}, 1, o.threads);
            const FailureRow row{base, widen, totalInk(r.image, bg) / referenceInk, objectsMissed(r.image, bg, centres),
                                 int(centres.size()), r.seconds};
            if (o.print)
                std::printf("  thin objects: adaptive %2d+256 %-9s found %5.1f%% of their contrast, missed %d of %d\n", base,
                            widen ? "widen" : "no-widen", 100. * row.inkFound, row.objectsMissed, row.objects);
            rows.push_back(row);
        }
    return rows;
}

// Timings depend on what else the machine does: say so ("" where /proc/loadavg is not).
std::string loadAverage() {
    std::ifstream in("/proc/loadavg");
    double load = 0.;
    if (!(in >> load)) return "";
    return " (load average " + fmt("%.1f", load) + " when the study wrote this)";
}

constexpr double kTargetRmse = 1e-3;

void writeIntroduction(std::ostream& md, const AntialiasingResult& result, const AntialiasingOptions& o) {
    md << "# What accuracy costs in time: antialiasing\n\n"
       << "Generated by `raylab study antialiasing" << (o.quick ? " --quick" : "") << "` (framework/study/); do not edit by hand.\n"
       << "Lab 5's scene, " << result.width << " x " << result.height << " pixels (" << result.silhouettePixels
       << " on the silhouette), rendered by the reference solutions with each sampler. Times are medians of "
       << o.repeats << " renders (" << (o.quick ? "here 1" : "1 for 1024 samples") << "), on this machine with "
       << (o.threads == 0 ? std::string("all cores") : std::to_string(o.threads) + " threads") << loadAverage() << ".\n\n"
       << "**The reference is exact.** The silhouette of a sphere on the camera's axis is exactly a circle on the screen, "
       << "and inside it the cosine has a closed form; each pixel's average is integrated by Gauss-Legendre quadrature, "
       << "exactly in one direction after the change of variable y = h sin(phi) that removes the square root at the rim, "
       << "and split at the points where the circle crosses the pixel's edges in the other. Doubling the nodes moves no "
       << "pixel by more than " << fmt("%.1e", result.referenceCheck) << ", far below the smallest error shown. "
       << "Sampling a reference instead would need about 10^10 samples a pixel to get there.\n\n"
       << "![RMSE on silhouette pixels against samples](accuracy_samples.svg)\n\n"
       << "![RMSE against time](accuracy_time.svg)\n\n";
}

// The convergence table; returns each sampler's seconds to kTargetRmse over the image (0 when not
// known).
std::map<std::string, double> writeConvergence(std::ostream& md, const std::map<std::string, SamplerSeries>& series) {
    md << "## Convergence\n\n| sampler | slope on silhouette pixels | slope of the image's RMSE against time | samples for RMSE "
       << fmt("%g", kTargetRmse) << " | seconds for RMSE " << fmt("%g", kTargetRmse) << " | samples for silhouette RMSE "
       << fmt("%g", kTargetRmse) << " |\n|---|---|---|---|---|---|\n";
    std::map<std::string, double> secondsToTarget;
    for (const std::string& name : kStudySamplers) {
        const auto it = series.find(name);
        if (it == series.end()) continue;
        const SamplerSeries& s = it->second;
        const std::string seconds = reach(s.seconds, s.rmse, kTargetRmse, "%.3g");
        md << "| " << name << " | " << fmt("%.2f", fittedSlope(s.samples, s.silhouette)) << " | "
           << fmt("%.2f", logLogSlope(s.seconds, s.rmse)) << " | " << reach(s.samples, s.rmse, kTargetRmse, "%.0f") << " | "
           << seconds << " | " << reach(s.samples, s.silhouette, kTargetRmse, "%.0f") << " |\n";
        secondsToTarget[name] = std::atof(seconds.c_str() + (seconds[0] == '~' ? 1 : 0));
    }
    md << "\nSlopes are least-squares fits of log error against log samples from 4 samples on (the first sample is not "
          "yet asymptotic). Theory for an edge: -0.5 for independent random samples, -0.75 for one sample per stratum. "
          "A \"~\" marks a count beyond the largest measured, extrapolated along the last three points. "
          "The RMSE of the image is over all its pixels and channels (linear values, no 8-bit rounding); most pixels are "
          "inside or outside the disc, where every sampler is nearly exact, so the image reaches a given RMSE far sooner "
          "than its silhouette pixels alone (last column).\n\n";
    return secondsToTarget;
}

// Who gets to the target error first, against uniform random sampling.
void writeFastest(std::ostream& md, const std::map<std::string, double>& secondsToTarget) {
    std::string best;
    for (const auto& [name, seconds] : secondsToTarget)
        if (seconds > 0. && (best.empty() || seconds < secondsToTarget.at(best))) best = name;
    const auto random = secondsToTarget.find("random");
    if (best.empty() || random == secondsToTarget.end() || !(random->second > 0.)) return;
    const double fastest = secondsToTarget.at(best);
    md << "- To reach an RMSE of " << fmt("%g", kTargetRmse) << " over the image, **" << best << "** gets there first, in "
       << fmt("%.3g", fastest) << " s against " << fmt("%.3g", random->second)
       << " s for uniform random sampling: " << fmt("%.0f", 100. * (1. - fastest / random->second)) << "% of the time saved.\n";
}

// What 4x more samples buy at the largest counts, random against stratified, on the silhouette.
void writeFourTimesMore(std::ostream& md, const std::map<std::string, SamplerSeries>& series) {
    const auto stratified = series.find("stratified"), random = series.find("random");
    if (stratified == series.end() || random == series.end() || stratified->second.silhouette.size() < 3) return;
    const SamplerSeries &s = stratified->second, &r = random->second;
    const std::size_t k = s.samples.size() - 1;
    md << "- What 4x more samples buy: on the silhouette, from " << fmt("%.0f", s.samples[k - 1]) << " to "
       << fmt("%.0f", s.samples[k]) << " samples the error of random sampling falls by "
       << fmt("%.2f", r.silhouette[k - 1] / r.silhouette[k]) << "x (theory: 2x), that of stratified sampling by "
       << fmt("%.2f", s.silhouette[k - 1] / s.silhouette[k]) << "x (theory: 4^0.75 = 2.83x).\n";
}

// The fastest widened 16+256 setting within 10% of uniform stratified 256's error, or none.
const StudyRow* bestAdaptiveAgainst(const std::vector<StudyRow>& rows, const StudyRow& uniform) {
    const StudyRow* best = nullptr;
    for (const StudyRow& r : rows)
        if (r.adaptive && r.adaptive->baseSamples == 16 && r.adaptive->widen && r.error.rmse <= 1.1 * uniform.error.rmse &&
            (best == nullptr || r.seconds < best->seconds))
            best = &r;
    return best;
}

void writeAdaptiveAgainstUniform(std::ostream& md, const std::vector<StudyRow>& rows) {
    const auto uniform = std::find_if(rows.begin(), rows.end(), [](const StudyRow& r) {
        return r.sampler == "stratified" && !r.adaptive && r.samples == 256.;
    });
    if (uniform == rows.end()) return;
    const StudyRow* best = bestAdaptiveAgainst(rows, *uniform);
    if (best == nullptr) {
        md << "- No adaptive setting measured here reached the error of uniform stratified 256.\n";
        return;
    }
    md << "- Adaptive sampling (stratified, 16 samples everywhere, the pixels whose samples differ by more than the "
          "threshold widened by one pixel, then 256 samples on them; setting " << settingName(*best) << ") reaches an RMSE of "
       << fmt("%.2e", best->error.rmse) << " against " << fmt("%.2e", uniform->error.rmse)
       << " for uniform stratified 256, in " << fmt("%.3g", best->seconds) << " s against "
       << fmt("%.3g", uniform->seconds) << " s: **" << fmt("%.2f", best->seconds / uniform->seconds)
       << " of the time** (1/" << fmt("%.1f", uniform->seconds / best->seconds) << "), rendering "
       << fmt("%.1f", 100. * best->refinedFraction) << "% of the pixels again.\n";
}

void writeFailure(std::ostream& md, const std::vector<FailureRow>& failure, const AntialiasingOptions& o) {
    md << "\n## The failure case: objects smaller than a pixel\n\n"
       << "`scenes/study/adaptive_thin_objects.toml`: 24 spheres 0.35 pixel across. Adaptive sampling (threshold 0.05, "
          "256 samples on the pixels it refines) against a stratified render with " << (o.quick ? 1024 : 4096) << " samples:\n\n"
       << "| first pass | widened by one pixel | contrast of the small objects found | objects missed entirely |\n|---|---|---|---|\n";
    for (const FailureRow& f : failure)
        md << "| " << f.baseSamples << " samples | " << (f.widen ? "yes" : "no") << " | " << fmt("%.0f", 100. * f.inkFound)
           << "% | " << f.objectsMissed << " of " << f.objects << " |\n";
    md << "\nA pixel is refined only when its first samples disagree, so an object that no first sample hits is never "
          "seen: with 4 samples a pixel, a 0.35-pixel object (a tenth of a pixel's area) escapes them most of the time. "
          "Without widening, a pixel that the object covers in part keeps its wrong first estimate while its neighbour is "
          "refined. With 16 samples and widening, the first pass sees the object in one of its pixels and the widening "
          "brings in the others.";
    if (!failure.empty() && failure[0].objectsMissed > 0)
        md << " Even then " << failure[0].objectsMissed << " of the " << failure[0].objects
           << " objects were missed here, because no first sample hit them: adaptive sampling cannot promise to find "
              "what is smaller than the spacing of its first samples.";
    md << "\n";
}

void writeMeasurements(std::ostream& md, const std::vector<StudyRow>& rows) {
    md << "\n## Every measurement\n\n| sampler | setting | samples | seconds | runs | RMSE | silhouette RMSE | PSNR (dB) | max error | refined |\n"
          "|---|---|---|---|---|---|---|---|---|---|\n";
    for (const StudyRow& r : rows)
        md << "| " << r.sampler << " | " << settingName(r) << " | " << fmt("%.1f", r.samples) << " | " << fmt("%.4f", r.seconds)
           << " | " << r.runs << " | " << fmt("%.3e", r.error.rmse) << " | " << fmt("%.3e", r.error.silhouetteRmse) << " | "
           << fmt("%.1f", r.error.psnr) << " | " << fmt("%.3e", r.error.maxError) << " | "
           << (r.adaptive ? fmt("%.2f%%", 100. * r.refinedFraction) : std::string()) << " |\n";
    md << "\nThe same numbers are in [accuracy.csv](accuracy.csv).\n";
}

void writeMarkdown(const std::filesystem::path& file, const AntialiasingResult& result, const AntialiasingOptions& o) {
    const auto series = seriesOf(result.rows);
    std::ostringstream md;
    writeIntroduction(md, result, o);
    const std::map<std::string, double> secondsToTarget = writeConvergence(md, series);
    md << "## Reading\n\n";
    writeFastest(md, secondsToTarget);
    writeFourTimesMore(md, series);
    writeAdaptiveAgainstUniform(md, result.rows);
    writeFailure(md, result.failure, o);
    writeMeasurements(md, result.rows);
    writeFileAtomically(file, md.str());
}

// The exact reference's own error (how much a pixel moves when the quadrature nodes double) and
// its silhouette pixels.
void checkReference(const CentredSphere& sphere, const ExactImage& exact, AntialiasingResult& result) {
    const ExactImage finer = exactCentredSphere(sphere, 32);
    for (std::size_t p = 0; p < exact.pixels.size(); ++p) {
        for (int c = 0; c < 3; ++c)
            result.referenceCheck = std::max(result.referenceCheck, std::abs(exact.pixels[p][c] - finer.pixels[p][c]));
        result.silhouettePixels += exact.coverage[p] > 1e-12 && exact.coverage[p] < 1. - 1e-12;
    }
}

} // namespace

std::string settingName(const StudyRow& row) {
    if (!row.adaptive) return "";
    const AdaptiveStudySetting& s = *row.adaptive;
    return std::to_string(s.baseSamples) + "+" + std::to_string(kAdaptiveMaxSamples) + " t=" + fmt("%g", s.threshold) +
           (s.widen ? " widen" : " no-widen");
}

AntialiasingResult runAntialiasingStudy(const AntialiasingOptions& o) {
    SceneDescription d = loadSceneFile(o.scene);
    if (o.quick) d.width = 120, d.height = 80;
    const CentredSphere sphere = centredSphere(d);
    AntialiasingResult result;
    result.width = d.width;
    result.height = d.height;
    const ExactImage exact = exactCentredSphere(sphere);
    checkReference(sphere, exact, result);
    if (o.print)
        std::printf("raylab study antialiasing: %s, %d x %d, %d silhouette pixels; exact reference (quadrature, "
                    "converged to %.1e)\n", d.id.c_str(), d.width, d.height, result.silhouettePixels, result.referenceCheck);
    const std::vector<int> counts = o.quick ? std::vector<int>{1, 4, 16, 64, 256} : std::vector<int>{1, 4, 16, 64, 256, 1024};
    result.rows = measureUniform(d, exact, o, counts);
    for (StudyRow& r : measureAdaptive(d, exact, o)) result.rows.push_back(std::move(r));
    result.failure = measureFailure(o);

    std::filesystem::create_directories(o.out);
    writeCsv(o.out / "accuracy.csv", result.rows);
    writePlots(o.out, result);
    writeMarkdown(o.out / "accuracy.md", result, o);
    if (o.print) std::printf("wrote accuracy.md, accuracy.csv, accuracy_samples.svg, accuracy_time.svg in %s\n", o.out.string().c_str());
    return result;
}

} // namespace raylab::study
