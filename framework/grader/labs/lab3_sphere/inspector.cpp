// Lab 3's rows of the pixel inspector (grader/inspector/inspector_steps.h), for a figure of one sphere
// drawn by one of lab 3's shadings: the hit of the reference's ray, the normal at the reference's hit
// and the colour, each asked of the student's function on the reference's inputs.
#include "grader/inspector/inspector_steps.h"
#include "probes.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace raylab::grader::inspector {

namespace {

// Lab 3's shadings as the probe Li numbers them (raylab/integrator.h's Shading); -1 for another.
int shadingIndex(const std::string& shading) {
    if (shading == "flat") return 0;
    if (shading == "placeholder_normal") return 1;
    if (shading == "cosine") return 2;
    return -1;
}

// The nearest t >= 0 where the ray meets the sphere (the handout's "which root"); nullopt on a miss.
std::optional<double> hitDistance(const glm::dvec3& centre, double radius, const ReferenceRay& r) {
    const glm::dvec3 oc = r.origin - centre;
    const double a = glm::dot(r.direction, r.direction), b = glm::dot(oc, r.direction);
    const double disc = b * b - a * (glm::dot(oc, oc) - radius * radius);
    if (disc < 0.) return std::nullopt;
    const double nearRoot = (-b - std::sqrt(disc)) / a, farRoot = (-b + std::sqrt(disc)) / a;
    if (nearRoot >= 0.) return nearRoot;
    if (farRoot >= 0.) return farRoot;
    return std::nullopt;
}

// colour * max(-d.n, 0), the cosine shading.
glm::dvec3 cosineShade(const glm::dvec3& colour, const glm::dvec3& d, const glm::dvec3& n) {
    return colour * std::max(-glm::dot(d, n), 0.);
}

void append(std::vector<double>& inputs, const glm::dvec3& v) { inputs.insert(inputs.end(), {v.x, v.y, v.z}); }

void sphere(PixelContext& pixel, Inspection& inspection) {
    const SceneDescription& d = pixel.scene;
    const int shading = shadingIndex(d.shading);
    if (!pixel.ray || pixel.coloured || shading < 0 || d.scene.objectCount() != 1 || d.scene.all<SphereGeometry>().size() != 1) return;
    const ReferenceRay& ray = *pixel.ray;
    const SphereGeometry& s = d.scene.all<SphereGeometry>().front();
    const glm::dvec3 centre(s.center()), colour(s.color()), background(d.scene.background);
    const std::optional<double> t = hitDistance(centre, s.radius(), ray);
    const glm::dvec3 position = t ? ray.origin + *t * ray.direction : glm::dvec3(0.);
    const glm::dvec3 normal = (position - centre) / double(s.radius());
    glm::dvec3 seen = background;
    if (t && shading == 0) seen = colour;
    if (t && shading == 1) {
        glm::dvec3 n = glm::normalize(glm::dvec3(1.));
        if (glm::dot(ray.direction, n) > 0.) n = -n;
        seen = cosineShade(colour, ray.direction, n);
    }
    if (t && shading == 2) seen = cosineShade(colour, ray.direction, normal);
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
