// Summing many samples of one pixel: float, compensated float, double, and the lab 5 code.
#include "numerics_study.h"

#include "raylab/perspective_camera.h"
#include "raylab/renderer.h"
#include "raylab/todo.h"

#include <cmath>
#include <string>

namespace raylab::study {

namespace {

// Kahan's compensated sum: c keeps the low-order bits that each addition to s rounds away
// (Higham, Accuracy and Stability of Numerical Algorithms, 4.3). Its error does not grow with n.
struct KahanSum {
    float s = 0.f, c = 0.f;
    void add(float x) {
        const float y = x - c;
        const float t = s + y;
        c = (t - s) - y;
        s = t;
    }
};

} // namespace

Table studyAccumulation(const StudyOptions& options) {
    // Lab 5's scene: the tp1 sphere with cosine shading, 600 x 400; pixel (400, 200) is inside the
    // disc, 100 pixels right of its centre, where the cosine is about 0.57 and varies in the pixel.
    const int i = 400, j = 200, width = 600, height = 400;
    const std::uint64_t seed = 1;
    Table table{"accumulation",
                "Blue channel of pixel (400, 200) of lab 5's scene (cosine shading, uniform random samples, seed 1): "
                "relative error of the average of n samples against a long double sum of the same samples",
                {"samples n", "float sum", "Kahan float sum", "double sum", "lab code: Renderer::renderPixel"},
                {}};
    const Scene scene = makeTp1Scene();
    const RayCastIntegrator integrator(Shading::Cosine);
    try {
        const PerspectiveCamera camera(width, height);
        for (std::int64_t n = 1000; n <= options.maxSamples; n *= 10) {
            // The samples as lab 5 takes them: the sampler of an n-sample pixel, the same float
            // expressions for the screen point.
            PixelSampler sampler(SamplerKind::Random, int(n), seed, i, j, width);
            float naive = 0.f;
            KahanSum kahan;
            double dsum = 0.;
            long double exact = 0.L;
            for (std::int64_t k = 0; k < n; ++k) {
                const glm::vec2 offset = sampler.next2D();
                const float b = integrator.Li(scene, camera.generateRay((float(i) + offset.x) / float(width),
                                                                        (float(j) + offset.y) / float(height))).b;
                naive += b;
                kahan.add(b);
                dsum += b;
                exact += b;
            }
            const long double mean = exact / n;
            auto err = [&](long double sum) { return double(std::abs(sum / n - mean) / mean); };
            std::string lab;
            try {
                Renderer renderer(scene, camera, integrator);
                renderer.setNbPixelSamples(int(n));
                PixelSampler labSampler(SamplerKind::Random, int(n), seed, i, j, width);
                lab = sci(double(std::abs(renderer.renderPixel(i, j, labSampler).b - mean) / mean));
            } catch (const NotDoneYet& e) {
                lab = e.what();
            }
            table.add({sci(double(n), 0), sci(err(naive)), sci(err(kahan.s)), sci(err(dsum)), lab});
        }
    } catch (const NotDoneYet& e) {
        table.add({"", e.what(), "", "", ""});
    }
    return table;
}

} // namespace raylab::study
