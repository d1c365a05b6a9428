// Lab 6's rows of the pixel inspector (grader/inspector/inspector_steps.h), for a figure drawn by its
// point light integrator: the nearest hit of the reference's ray, then for each light the shadow ray
// the reference casts (origin, direction), the light it tests, what it meets on the way (the
// occluders, the nearest one's t), whether the point is in shadow and Lambert's term; last the
// pixel's colour in both pictures. The student's values: inShadow asked once for each object of the
// scene alone (the point is in shadow when one of them hides the light: what the objects their
// inShadow finds on the way are), and Li asked with the hit object alone, the light alone, no ambient
// and no shadow test (its Lambert term), both on the reference's hit. The shadow ray itself is the
// reference's: no function of the lab hands it back.
#include "answers.h"
#include "grader/inspector/inspector_steps.h"
#include "probes.h"

#include "src/messages.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

namespace raylab::grader::inspector {

namespace {

// The shadow ray's start, as the handout sets it (shadow acne).
constexpr double kShadowRayStart = 1e-4;

// An object of the scene: a sphere (radius > 0) or a plane.
struct Object {
    bool sphere = true;
    int index = 0; // among its kind, from 1
    glm::dvec3 centre{0.}, normal{0.}, colour{0.};
    double radius = 0.;

    std::string name() const { return tr(sphere ? "watch.lab6.sphere" : "watch.lab6.plane", {{"k", std::to_string(index)}}); }
    // The t in (tMin, tMax) where the ray meets it first; nullopt when none.
    std::optional<double> hit(const ReferenceRay& r, double tMin, double tMax) const {
        const std::optional<double> t = sphere ? lab6::sphereCrossing(centre, radius, r.origin, r.direction, tMin)
                                               : lab6::planeCrossing(centre, normal, r.origin, r.direction, tMin);
        return t && *t < tMax ? t : std::nullopt;
    }
    // The probes' scene of this object alone: the other kind left out (radius 0, normal 0).
    probes::Objects alone() const {
        if (sphere) return {{centre, radius}, {}};
        return {{}, {centre, normal}};
    }
    // The same with its colour (Li's).
    probes::ColouredObjects aloneColoured() const {
        const probes::Objects objects = alone();
        return {objects.sphere, sphere ? colour : glm::dvec3(0.), objects.plane, sphere ? glm::dvec3(0.) : colour};
    }
};

std::vector<Object> objects(const Scene& scene) {
    std::vector<Object> all;
    int k = 0;
    for (const SphereGeometry& s : scene.all<SphereGeometry>())
        all.push_back({true, ++k, glm::dvec3(s.center()), {}, glm::dvec3(s.color()), double(s.radius())});
    k = 0;
    for (const Plane& p : scene.all<Plane>())
        all.push_back({false, ++k, glm::dvec3(p.point()), glm::normalize(glm::dvec3(p.normal())), glm::dvec3(p.color())});
    return all;
}

// Names joined, or "none".
std::string named(const std::vector<std::string>& names) {
    if (names.empty()) return tr("watch.lab6.none");
    std::string text;
    for (const std::string& n : names) text += (text.empty() ? "" : ", ") + n;
    return text;
}

// The rows of light `k`'s shadow ray from `position` (to `lightPosition`, `distance` away, along `l`):
// its origin and direction, what it meets (the reference's, and the objects the student's inShadow
// finds, each asked alone), the nearest occluder's t, and whether the point is in shadow.
void shadowRayRows(Inspection& inspection, const std::vector<Object>& scene, int k, const glm::dvec3& position,
                   const glm::dvec3& lightPosition, const glm::dvec3& l, double distance) {
    const ReferenceRay shadowRay{position, l};
    inspection.add({.key = "shadow_origin", .lab = 6, .reference = shown(position), .index = k, .referenceOnly = true,
                    .takes = {"ray"}});
    inspection.add({.key = "shadow_direction", .lab = 6, .reference = shown(l), .index = k, .referenceOnly = true,
                    .takes = {"ray"}});
    std::vector<std::string> hiding, names;
    std::optional<double> nearestOccluder;
    std::vector<int> calls;
    for (const Object& o : scene) {
        names.push_back(o.name());
        if (const std::optional<double> at = o.hit(shadowRay, kShadowRayStart, distance)) {
            hiding.push_back(o.name());
            if (!nearestOccluder || *at < *nearestOccluder) nearestOccluder = *at;
        }
        calls.push_back(inspection.call(probes::inShadow(o.alone(), position, lightPosition)));
    }
    // The objects the student's inShadow finds between the point and the light, each alone.
    const auto theirs = [calls, names](const Outputs& outputs) -> Json {
        std::vector<std::string> found;
        for (std::size_t c = 0; c < calls.size(); ++c) {
            const Json answer = answerOf(probes::inShadow, calls[c])(outputs);
            if (answer.is_null()) return {};
            if (answer == true) found.push_back(names[c]);
        }
        return named(found);
    };
    inspection.add({.key = "occluders", .function = "inShadow", .lab = 6, .reference = named(hiding), .student = theirs,
                    .index = k, .takes = {"ray"}});
    if (nearestOccluder)
        inspection.add({.key = "occluder_t", .lab = 6, .reference = *nearestOccluder, .index = k, .referenceOnly = true,
                        .takes = {"ray"}});
    const std::string none = named({});
    inspection.add({.key = "in_shadow", .function = "inShadow", .lab = 6, .reference = !hiding.empty(),
                    .student = [theirs, none](const Outputs& outputs) -> Json {
                        const Json found = theirs(outputs);
                        return found.is_null() ? Json() : Json(found != none);
                    },
                    .index = k, .takes = {"ray"}});
}

void shadows(PixelContext& pixel, Inspection& inspection) {
    const SceneDescription& d = pixel.scene;
    const bool withShadows = d.shading == "point_light";
    if (!pixel.ray || pixel.coloured || !(withShadows || d.shading == "point_light_no_shadows")) return;
    const ReferenceRay& ray = *pixel.ray;
    const std::vector<Object> scene = objects(d.scene);
    // The nearest hit (the primary rays' t from 0).
    const Object* nearest = nullptr;
    double t = std::numeric_limits<double>::infinity();
    for (const Object& o : scene)
        if (const std::optional<double> at = o.hit(ray, 0., t)) {
            t = *at;
            nearest = &o;
        }
    inspection.add({.key = "lab6_hit", .lab = 6, .reference = nearest ? nearest->name() : tr("watch.lab6.none"),
                    .referenceOnly = true, .takes = {"ray"}});
    if (nearest == nullptr) {
        pixel.coloured = true;
        return;
    }
    const glm::dvec3 position = ray.origin + t * ray.direction;
    glm::dvec3 n = nearest->sphere ? (position - nearest->centre) / nearest->radius : nearest->normal;
    if (glm::dot(n, ray.direction) > 0.) n = -n; // the side the ray sees
    inspection.add({.key = "lab6_t", .lab = 3, .reference = t, .referenceOnly = true, .takes = {"ray"}});
    inspection.add({.key = "lab6_position", .lab = 3, .reference = shown(position), .referenceOnly = true, .takes = {"ray"}});
    inspection.add({.key = "lab6_normal", .lab = 6, .reference = shown(n), .referenceOnly = true, .takes = {"ray"}});
    const std::string liFunction = "PointLightIntegrator::Li";
    const probes::Ray probeRay{ray.origin, ray.direction};
    int k = 0;
    for (const PointLight& light : d.scene.lights) {
        ++k;
        const glm::dvec3 lightPosition(light.position), intensity(light.intensity);
        const glm::dvec3 toLight = lightPosition - position;
        const double distance = glm::length(toLight);
        const glm::dvec3 l = toLight / distance;
        inspection.add({.key = "lab6_light", .lab = 6, .reference = shown(lightPosition), .index = k});
        if (withShadows) shadowRayRows(inspection, scene, k, position, lightPosition, l, distance);
        // Lambert's term of this light alone: colour / pi * I * max(n . l, 0) / r^2.
        const glm::dvec3 lambert = nearest->colour * std::numbers::inv_pi * intensity * (std::max(glm::dot(n, l), 0.) / (distance * distance));
        // Li with no ambient term and no shadow test gives it.
        const int lambertCall = inspection.call(probes::pointLightLi(0., false, nearest->aloneColoured(), {lightPosition, intensity},
                                                                     glm::dvec3(d.scene.background), probeRay));
        inspection.add({.key = "lambert", .function = liFunction, .lab = 6, .reference = shown(lambert),
                        .student = answerOf(probes::pointLightLi, lambertCall), .index = k, .takes = {"ray"}});
    }
    const Json yours = pixel.picturePixel("student");
    inspection.add({.key = "lab6_picture", .function = liFunction, .lab = 6, .reference = pixel.picturePixel("reference"),
                    .student = [yours](const Outputs&) { return yours; }});
    pixel.coloured = true;
}

} // namespace

RAYLAB_REGISTER_INSPECTOR_STEP(InspectorStage::Path, shadows);

} // namespace raylab::grader::inspector
