// Lab 5's rows of the pixel inspector (grader/inspector/inspector_steps.h): the pixel's screen points
// and their average, asked of renderPixel (with a camera that records the points and an integrator
// whose colour is the point: the average is the mean point), the reference's from the framework's
// sampler with the scene's seed, as the figure draws them; then the pixel's colour in both pictures.
#include "grader/inspector/inspector_steps.h"
#include "probes.h"

#include "raylab/sampler.h"

#include <algorithm>
#include <vector>

namespace raylab::grader::inspector {

namespace {

// The most samples a pixel's inspection lists one by one.
constexpr int kListedSamples = 8;

// Screen point k the student's renderPixel asked for (call `call`), (sx, sy); null when it gave no
// answer or asked for fewer points.
StudentValue screenPoint(int call, std::size_t k) {
    return answerOf(probes::renderPixel, call, [k](const probes::Rendered& r) -> Json {
        if (k >= r.points.size()) return {};
        return Json::array({shown(r.points[k].x), shown(r.points[k].y)});
    });
}

void samples(PixelContext& pixel, Inspection& inspection) {
    const SceneDescription& d = pixel.scene;
    if (d.samples <= 1 || d.sampler != SamplerKind::Random || d.camera.lookAt || pixel.ray || pixel.coloured) return;
    const int x = pixel.x, y = pixel.y;
    PixelSampler sampler(d.sampler, d.samples, d.seed, x, y, d.width);
    glm::dvec3 mean(0.);
    std::vector<glm::dvec2> points;
    for (int k = 0; k < d.samples; ++k) {
        const glm::vec2 offset = sampler.next2D();
        points.emplace_back((float(x) + offset.x) / float(d.width), (float(y) + offset.y) / float(d.height));
        mean += glm::dvec3(points.back(), 1.) / double(d.samples);
    }
    const int c = inspection.call(probes::renderPixel(d.width, d.height, x, y, d.samples, double(d.seed)));
    const std::string function = "Renderer::renderPixel";
    inspection.add({.key = "lab5_samples", .function = function, .lab = 5, .reference = d.samples,
                    .student = answerOf(probes::renderPixel, c,
                                        [](const probes::Rendered& r) { return double(r.points.size()); })});
    for (int k = 0; k < std::min(d.samples, kListedSamples); ++k)
        inspection.add({.key = "lab5_sample", .function = function, .lab = 5,
                        .reference = Json::array({points[std::size_t(k)].x, points[std::size_t(k)].y}),
                        .student = screenPoint(c, std::size_t(k)), .index = k + 1});
    inspection.add({.key = "lab5_average", .function = function, .lab = 5, .reference = shown(mean),
                    .student = answerOf(probes::renderPixel, c, &probes::Rendered::colour)});
    const Json yours = pixel.picturePixel("student");
    inspection.add({.key = "lab5_picture", .function = function, .lab = 5, .reference = pixel.picturePixel("reference"),
                    .student = [yours](const Outputs&) { return yours; }});
    pixel.coloured = true;
}

} // namespace

RAYLAB_REGISTER_INSPECTOR_STEP(InspectorStage::Ray, samples);

} // namespace raylab::grader::inspector
