// Lab 3's rows of the pixel inspector (grader/inspector/inspector_steps.h), for a figure of one sphere
// drawn by one of lab 3's shadings: the hit of the reference's ray, the normal at the reference's hit
// and the colour, each asked of the student's function on the reference's inputs.
#include "answers.h"
#include "grader/inspector/inspector_steps.h"
#include "probes.h"

#include <limits>
#include <optional>

namespace raylab::grader::inspector {

namespace {

// Lab 3's shadings as the probe Li numbers them (answers.h); -1 for another.
int shadingIndex(const std::string& shading) {
    if (shading == "flat") return lab3::kFlat;
    if (shading == "placeholder_normal") return lab3::kPlaceholder;
    if (shading == "cosine") return lab3::kCosine;
    return -1;
}

void sphere(PixelContext& pixel, Inspection& inspection) {
    const SceneDescription& d = pixel.scene;
    const int shading = shadingIndex(d.shading);
    if (!pixel.ray || pixel.coloured || shading < 0 || d.scene.objectCount() != 1 || d.scene.all<SphereGeometry>().size() != 1) return;
    const ReferenceRay& ray = *pixel.ray;
    const SphereGeometry& s = d.scene.all<SphereGeometry>().front();
    const glm::dvec3 centre(s.center()), colour(s.color()), background(d.scene.background);
    const std::optional<double> t = lab3::nearestHit(centre, s.radius(), ray.origin, ray.direction);
    const glm::dvec3 position = t ? ray.origin + *t * ray.direction : glm::dvec3(0.);
    const glm::dvec3 normal = (position - centre) / double(s.radius());
    const glm::dvec3 seen = t ? lab3::shade(shading, colour, ray.direction, normal) : background;
    const probes::Sphere probeSphere{centre, s.radius()};
    const probes::Ray probeRay{ray.origin, ray.direction};
    const int hit = inspection.call(probes::intersect(probeSphere, probeRay, 0., std::numeric_limits<double>::infinity()));
    const std::string intersect = "SphereGeometry::intersect";
    inspection.add({.key = "lab3_hit", .function = intersect, .lab = 3, .reference = t.has_value(),
                    .student = answerOf(probes::intersect, hit, &probes::Hit::found), .gives = "hit", .takes = {"ray"}});
    if (t) {
        inspection.add({.key = "lab3_t", .function = intersect, .lab = 3, .reference = *t,
                        .student = answerOf(probes::intersect, hit, &probes::Hit::t), .gives = "hit", .takes = {"ray"}});
        inspection.add({.key = "lab3_position", .function = intersect, .lab = 3, .reference = shown(position),
                        .student = answerOf(probes::intersect, hit, &probes::Hit::position), .gives = "hit", .takes = {"ray"}});
        const int normalCall = inspection.call(probes::computeNormal(probeSphere, position));
        inspection.add({.key = "lab3_normal", .function = "SphereGeometry::computeNormal", .lab = 3, .reference = shown(normal),
                        .student = answerOf(probes::computeNormal, normalCall), .takes = {"ray", "hit"}});
    }
    const int colourCall = inspection.call(probes::li(shading, probeSphere, colour, background, probeRay));
    inspection.add({.key = "lab3_colour", .function = "RayCastIntegrator::Li", .lab = 3, .reference = shown(seen),
                    .student = answerOf(probes::li, colourCall), .takes = {"ray"}});
    pixel.coloured = true;
}

} // namespace

RAYLAB_REGISTER_INSPECTOR_STEP(InspectorStage::Path, sphere);

} // namespace raylab::grader::inspector
