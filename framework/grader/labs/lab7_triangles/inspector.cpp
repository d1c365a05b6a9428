// Lab 7's rows of the pixel inspector (grader/inspector/inspector_steps.h), for a figure with
// triangles: whether the reference's ray crosses each triangle, then the nearest one crossed, where
// (t, the hit point) and its normal, each asked of the student's functions on that triangle and the
// reference's ray (the normal at the reference's hit).
#include "answers.h"
#include "grader/inspector/inspector_steps.h"
#include "probes.h"

#include "shapes.h"

#include <limits>
#include <optional>

namespace raylab::grader::inspector {

namespace {

probes::Triangle probeTriangle(const Triangle& triangle) {
    return {glm::dvec3(triangle.a()), glm::dvec3(triangle.b()), glm::dvec3(triangle.c())};
}

// Scenes of at most this many triangles show whether the ray crosses each; larger ones, the nearest only.
constexpr std::size_t kTrianglesListed = 16;

void triangles(PixelContext& pixel, Inspection& inspection) {
    const std::vector<Triangle>& all = pixel.scene.scene.all<Triangle>();
    if (!pixel.ray || all.empty()) return;
    const ReferenceRay& ray = *pixel.ray;
    // Where the ray crosses each triangle, in double; the nearest crossing with t >= 0.
    std::vector<std::optional<double>> crossedAt;
    std::size_t nearest = all.size();
    for (const Triangle& triangle : all) {
        const std::optional<lab7::Crossing> x =
            lab7::crossing(glm::dvec3(triangle.a()), glm::dvec3(triangle.b()), glm::dvec3(triangle.c()), ray.origin, ray.direction);
        crossedAt.push_back(x && x->inside() && x->t >= 0. ? std::optional<double>(x->t) : std::nullopt);
        if (crossedAt.back() && (nearest == all.size() || *crossedAt.back() < *crossedAt[nearest])) nearest = crossedAt.size() - 1;
    }
    const std::string intersect = "Triangle::intersect";
    const probes::Ray probeRay{ray.origin, ray.direction};
    const auto askIntersect = [&](const Triangle& triangle) {
        return inspection.call(
            probes::triangleIntersect(probeTriangle(triangle), probeRay, 0., std::numeric_limits<double>::infinity()));
    };
    // Whether it crosses each triangle: a triangle that is not crossed but hit differs here.
    std::vector<int> calls(all.size(), -1);
    if (all.size() <= kTrianglesListed)
        for (std::size_t k = 0; k < all.size(); ++k) {
            calls[k] = askIntersect(all[k]);
            inspection.add({.key = "lab7_crossed", .function = intersect, .lab = 7, .reference = crossedAt[k].has_value(),
                            .student = answerOf(probes::triangleIntersect, calls[k], &probes::Hit::found), .index = int(k) + 1,
                            .takes = {"ray"}});
        }
    if (nearest == all.size()) return;
    const int hit = calls[nearest] >= 0 ? calls[nearest] : askIntersect(all[nearest]);
    const double t = *crossedAt[nearest];
    const glm::dvec3 position = ray.origin + t * ray.direction;
    inspection.add({.key = "lab7_nearest", .lab = 7, .reference = int(nearest) + 1, .student = {}, .referenceOnly = true});
    inspection.add({.key = "lab7_t", .function = intersect, .lab = 7, .reference = t,
                    .student = answerOf(probes::triangleIntersect, hit, &probes::Hit::t), .gives = "hit", .takes = {"ray"}});
    inspection.add({.key = "lab7_position", .function = intersect, .lab = 7, .reference = shown(position),
                    .student = answerOf(probes::triangleIntersect, hit, &probes::Hit::position), .gives = "hit",
                    .takes = {"ray"}});
    const probes::Triangle triangle = probeTriangle(all[nearest]);
    const int normalCall = inspection.call(probes::triangleNormal(triangle, position));
    inspection.add({.key = "lab7_normal", .function = "Triangle::computeNormal", .lab = 7,
                    .reference = shown(lab7::normal(triangle.a, triangle.b, triangle.c)),
                    .student = answerOf(probes::triangleNormal, normalCall), .takes = {"ray", "hit"}});
}

} // namespace

RAYLAB_REGISTER_INSPECTOR_STEP(InspectorStage::Path, triangles);

} // namespace raylab::grader::inspector
