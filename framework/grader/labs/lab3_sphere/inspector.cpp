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

void append(std::vector<double>& inputs, const glm::dvec3& v) { inputs.insert(inputs.end(), {v.x, v.y, v.z}); }

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
    std::vector<double> sphereInputs;
    append(sphereInputs, centre);
    sphereInputs.push_back(s.radius());
    std::vector<double> intersectInputs = sphereInputs;
    append(intersectInputs, ray.origin);
    append(intersectInputs, ray.direction);
    intersectInputs.insert(intersectInputs.end(), {0., std::numeric_limits<double>::infinity()});
    const int hit = inspection.call(probes::intersect, intersectInputs); // hit, t, position
    const std::string intersect = "SphereGeometry::intersect";
    inspection.add({.key = "lab3_hit", .function = intersect, .lab = 3, .reference = t.has_value(), .student = values(hit, 0, 0),
                    .gives = "hit", .takes = {"ray"}});
    if (t) {
        inspection.add({.key = "lab3_t", .function = intersect, .lab = 3, .reference = *t, .student = values(hit, 1, 1), .gives = "hit",
                        .takes = {"ray"}});
        inspection.add({.key = "lab3_position", .function = intersect, .lab = 3, .reference = vec(position),
                        .student = values(hit, 2, 3), .gives = "hit", .takes = {"ray"}});
        std::vector<double> normalInputs = sphereInputs;
        append(normalInputs, position);
        inspection.add({.key = "lab3_normal", .function = "SphereGeometry::computeNormal", .lab = 3, .reference = vec(normal),
                        .student = values(inspection.call(probes::computeNormal, normalInputs), 0, 3), .takes = {"ray", "hit"}});
    }
    std::vector<double> liInputs{double(shading)};
    liInputs.insert(liInputs.end(), sphereInputs.begin(), sphereInputs.end());
    append(liInputs, colour);
    append(liInputs, background);
    append(liInputs, ray.origin);
    append(liInputs, ray.direction);
    inspection.add({.key = "lab3_colour", .function = "RayCastIntegrator::Li", .lab = 3, .reference = vec(seen),
                    .student = values(inspection.call(probes::li, liInputs), 0, 3), .takes = {"ray"}});
    pixel.coloured = true;
}

} // namespace

RAYLAB_REGISTER_INSPECTOR_STEP(InspectorStage::Path, sphere);

} // namespace raylab::grader::inspector
