// The image-level measurements: the far sphere's disc, degenerate cameras, pixel centres.
#include "numerics_study.h"
#include "sphere_formulas.h"

#include "raylab/integrator.h"
#include "raylab/perspective_camera.h"
#include "raylab/scene.h"
#include "raylab/todo.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

namespace raylab::study {

namespace {

using LD = long double;
constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr int kDiscImage = 256;     // the far disc's image is 256 x 256
constexpr double kDiscPixels = 80.; // and the disc's radius about 80 pixels

// The fovy at which a radius-1 sphere `distance` away, on the axis, has a silhouette of
// radius `pixels` in an image `size` pixels high: the silhouette is the cone of half-angle
// asin(r / D), which meets the screen (focal 1) in a circle of radius tan(asin(r / D)).
double fovyForDisc(double distance, double pixels, int size) {
    const double screenRadius = std::tan(std::asin(1. / distance));
    return glm::degrees(2. * std::atan(screenRadius * (size / 2.) / pixels));
}

// The far disc's three methods (the lab code, the textbook float formula, the stable float one):
// pixels hit, pixels whose hit or miss the long double truth contradicts, and the worst cosine
// error in 8-bit levels.
struct DiscCounts {
    static constexpr const char* kMethods[3] = {"lab code (float)", "textbook float", "stable float"};
    std::int64_t hits[3] = {0, 0, 0}, wrong[3] = {0, 0, 0}, levels[3] = {0, 0, 0};
};

// The disc's analytic area in pixels, from the camera's own float viewport: the silhouette's radius
// on the screen over half the screen's height, times half the image's height.
double analyticDiscArea(const PerspectiveCamera& camera, const glm::vec3& centre) {
    const LD screenRadius = std::tan(std::asin(LD(1) / LD(centre.z)));
    const LD radiusPx = screenRadius / (LD(camera.viewportHeight()) / 2) * (kDiscImage / 2.L);
    return double(std::numbers::pi_v<LD> * radiusPx * radiusPx);
}

// One ray per pixel centre of the camera through the three methods, against long double.
DiscCounts measureDisc(const PerspectiveCamera& camera, const glm::vec3& centre) {
    const SphereGeometry sphere(centre, 1.f, Color(1.f));
    Scene scene;
    scene.add(sphere);
    const RayCastIntegrator cosine(Shading::Cosine);
    DiscCounts counts;
    auto level = [](LD v) { return std::int64_t(std::llround(255.L * std::clamp(v, LD(0), LD(1)))); };
    for (int j = 0; j < kDiscImage; ++j)
        for (int i = 0; i < kDiscImage; ++i) {
            const Ray ray = camera.generateRay((float(i) + 0.5f) / float(kDiscImage), (float(j) + 0.5f) / float(kDiscImage));
            const V3<LD> o = V3<LD>::from(ray.origin), d = V3<LD>::from(ray.direction), c = V3<LD>::from(centre);
            const SphereHit<LD> truth = stableIntersect(o, d, c, LD(1), LD(0), LD(kInf));
            const V3<float> of = V3<float>::from(ray.origin), df = V3<float>::from(ray.direction), cf = V3<float>::from(centre);
            const SphereHit<float> foil = textbookIntersect(of, df, cf, 1.f, 0.f, kInf);
            const SphereHit<float> stable = stableIntersect(of, df, cf, 1.f, 0.f, kInf);
            HitRecord hit;
            const bool got[3] = {sphere.intersect(ray, 0.f, kInf, hit), foil.hit, stable.hit};
            // The cosine -d.n of each, where it and the truth both hit.
            auto shade = [&](const V3<float>& n) { return -LD(dot(df, n)); };
            const LD shades[3] = {LD(cosine.Li(scene, ray).b), shade(normalAt(of, df, cf, 1.f, foil.t)),
                                  shade(normalAt(of, df, cf, 1.f, stable.t))};
            const LD exactShade = -dot(d, normalAt(o, d, c, LD(1), truth.t));
            for (int m = 0; m < 3; ++m) {
                counts.hits[m] += got[m];
                counts.wrong[m] += got[m] != truth.hit;
                if (got[m] && truth.hit) counts.levels[m] = std::max(counts.levels[m], std::abs(level(shades[m]) - level(exactShade)));
            }
        }
    return counts;
}

} // namespace

Table studyFarDisc() {
    Table table{"far_disc",
                "A radius-1 sphere on the axis of the default camera, " + std::to_string(kDiscImage) + " x " +
                    std::to_string(kDiscImage) + " pixels, fovy chosen for a disc of radius 80 px; one ray per pixel "
                    "centre from the lab 2 code; pixels counted against the analytic disc area; cosine shading "
                    "(lab 3's RayCastIntegrator for the lab code) against long double, in 8-bit levels",
                {"distance", "fovy (deg)", "method", "pixels hit", "analytic area (px)", "area error %",
                 "pixels wrong vs long double", "max cosine error (8-bit levels)"},
                {}};
    for (double distance : {1e2, 1e3, 1e4, 1e5}) {
        const float fovy = float(fovyForDisc(distance, kDiscPixels, kDiscImage));
        const glm::vec3 centre(0.f, 0.f, float(distance));
        try {
            const PerspectiveCamera camera(kDiscImage, kDiscImage, fovy);
            const double area = analyticDiscArea(camera, centre);
            const DiscCounts counts = measureDisc(camera, centre);
            for (int m = 0; m < 3; ++m)
                table.add({sci(distance, 0), sci(fovy, 3), DiscCounts::kMethods[m], std::to_string(counts.hits[m]),
                           fixed(area, 1), fixed(100. * (double(counts.hits[m]) - area) / area, 3),
                           std::to_string(counts.wrong[m]), std::to_string(counts.levels[m])});
        } catch (const NotDoneYet& e) {
            table.add({sci(distance, 0), sci(fovy, 3), "lab code", e.what(), "", "", "", ""});
        }
    }
    return table;
}

namespace {

// The textbook camera with no checks: lookAt basis, then the lab 2 viewport, then 16 x 16 rays.
// Returns how many ray directions are NaN or infinite, and how many are distinct.
struct NaiveRays {
    int nonFinite = 0;
    int distinct = 0;
};

NaiveRays naiveCamera(const glm::vec3& position, const glm::vec3& target, const glm::vec3& up, float fovy) {
    const glm::vec3 w = glm::normalize(position - target);
    const glm::vec3 u = glm::normalize(glm::cross(up, w));
    const glm::vec3 v = glm::cross(w, u);
    const float height = 2.f * std::tan(glm::radians(fovy) / 2.f), width = height * 1.5f;
    const glm::vec3 topLeft = position - w + v * (height / 2.f) - u * (width / 2.f);
    NaiveRays result;
    std::vector<glm::vec3> seen;
    for (int j = 0; j < 16; ++j)
        for (int i = 0; i < 16; ++i) {
            const glm::vec3 point = topLeft + ((float(i) + 0.5f) / 16.f) * width * u - ((float(j) + 0.5f) / 16.f) * height * v;
            const glm::vec3 d = glm::normalize(point - position);
            if (!std::isfinite(d.x) || !std::isfinite(d.y) || !std::isfinite(d.z)) {
                ++result.nonFinite;
                continue;
            }
            bool known = false;
            for (const glm::vec3& s : seen) known = known || glm::length(s - d) < 1e-6f;
            if (!known) seen.push_back(d);
        }
    result.distinct = int(seen.size());
    return result;
}

// What raylab says: the checks of figure.cpp, then the camera's constructors.
std::string raylabSays(const glm::vec3& position, const glm::vec3& target, const glm::vec3& up, float fovy) {
    try {
        checkLookAtParameters(position, target, up);
        const PerspectiveCamera camera(600, 400, position, target, up, fovy);
        return "accepted";
    } catch (const std::invalid_argument& e) {
        return std::string("error: ") + e.what();
    } catch (const NotDoneYet& e) {
        return e.what();
    }
}

} // namespace

Table studyDegenerateCameras() {
    Table table{"degenerate_cameras",
                "A camera with no checks (lookAt basis, then the lab 2 screen) shooting 16 x 16 rays, against what "
                "raylab says for the same parameters",
                {"case", "naive: NaN rays of 256", "naive: distinct rays", "raylab"},
                {}};
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const glm::vec3 o(0.f), z(0.f, 0.f, 1.f), y(0.f, 1.f, 0.f);
    struct Case {
        const char* name;
        glm::vec3 position, target, up;
        float fovy;
    };
    const Case cases[] = {
        {"a sound camera (for comparison)", o, z, y, 60.f},
        {"up parallel to the view direction", o, glm::vec3(0.f, 5.f, 0.f), y, 60.f},
        {"position equal to the target", glm::vec3(1.f, 2.f, 3.f), glm::vec3(1.f, 2.f, 3.f), y, 60.f},
        {"up = (0, 0, 0)", o, z, glm::vec3(0.f), 60.f},
        {"fovy = 0", o, z, y, 0.f},
        {"fovy = 180", o, z, y, 180.f},
        {"fovy = 270", o, z, y, 270.f},
        {"fovy = NaN", o, z, y, nan},
        {"position infinite", glm::vec3(kInf, 0.f, 0.f), z, y, 60.f},
        {"target NaN", o, glm::vec3(nan, 0.f, 1.f), y, 60.f},
    };
    for (const Case& c : cases) {
        const NaiveRays naive = naiveCamera(c.position, c.target, c.up, c.fovy);
        table.add({c.name, std::to_string(naive.nonFinite), std::to_string(naive.distinct),
                   raylabSays(c.position, c.target, c.up, c.fovy)});
    }
    return table;
}

Table studyPixelCentres() {
    Table table{"pixel_centres",
                "Pixel centres sx = (i + 0.5) / W computed in float for every column i of a W-pixel-wide image",
                {"W", "columns sharing their sx with another", "max |sx - exact| in pixels", "raylab"},
                {}};
    for (std::int64_t width : {std::int64_t(16384), std::int64_t(100003), std::int64_t(1048573), std::int64_t(1) << 23,
                               (std::int64_t(1) << 23) + 1, std::int64_t(1) << 24, std::int64_t(1) << 25}) {
        std::int64_t shared = 0;
        double worst = 0.;
        float previous = -1.f;
        for (std::int64_t i = 0; i < width; ++i) {
            const float sx = (float(i) + 0.5f) / float(width);
            if (sx == previous) ++shared;
            previous = sx;
            worst = std::max(worst, std::abs(double(sx) * double(width) - (double(i) + 0.5)));
        }
        std::string says = "accepted";
        try {
            const PerspectiveCamera camera(int(std::min<std::int64_t>(width, INT32_MAX)), 1);
        } catch (const std::exception& e) {
            says = std::string("error: ") + e.what();
        }
        table.add({std::to_string(width), std::to_string(shared), sci(worst, 2), says});
    }
    return table;
}

} // namespace raylab::study
