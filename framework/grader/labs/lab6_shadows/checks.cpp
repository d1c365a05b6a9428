// Lab 6's function checks: the shadow test (a lit point, a shadowed point, a point its own surface
// must not shadow, an object beyond the light) and the shading from a point light, with and without
// the test. Every check holds points that must be lit and points that must be in shadow, so that an
// answer that never changes earns none of them.
#include "answers.h"
#include "grader/judge/checks/checks.h"
#include "probes.h"

#include "src/messages.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>
#include <optional>

namespace raylab::grader {

namespace {

using probes::Light;
using probes::Plane;
using probes::Ray;
using probes::Sphere;

// The t of the ray's nearest crossing of each object with t > tMin, in double.
// (A radius of 0 is no sphere, a normal of 0 no plane.)
std::optional<double> crossing(const Sphere& s, const Ray& r, double tMin) {
    if (s.radius == 0.) return std::nullopt;
    return lab6::sphereCrossing(s.centre, s.radius, r.origin, r.direction, tMin);
}
std::optional<double> crossing(const Plane& p, const Ray& r, double tMin) {
    return lab6::planeCrossing(p.point, p.normal, r.origin, r.direction, tMin);
}

// A probe's scene: one sphere and one plane, either left out, and its light.
struct ShadowScene {
    Sphere sphere;
    Plane plane;
    Light light;
};

// Whether an object lies strictly between `point` (on a surface, exactly, in double) and the light.
bool occluded(const ShadowScene& s, const glm::dvec3& point) {
    const glm::dvec3 toLight = s.light.position - point;
    const double distance = glm::length(toLight);
    const Ray shadowRay{point, toLight / distance};
    constexpr double kLeaves = 1e-9; // the point's own surface, crossed at t = 0
    const auto before = [distance](std::optional<double> t) { return t && *t < distance; };
    return before(crossing(s.sphere, shadowRay, kLeaves)) || before(crossing(s.plane, shadowRay, kLeaves));
}

std::string describe(const Sphere& s) {
    return tr("what.lab6.sphere", {{"centre", show(s.centre)}, {"radius", show(s.radius)}});
}

// One inShadow call and its answer. A companion case (`companion`) is there only so that a constant
// answer fails: it is judged with its own hint, which says so.
struct ShadowCase {
    std::string what;
    ShadowScene scene;
    glm::dvec3 point;
    bool inShadow = false;
    std::string hint;
};

protocol::Call shadowCall(const ShadowScene& s, const glm::dvec3& point) {
    return probes::inShadow({s.sphere, s.plane}, point, s.light.position);
}

void addShadowCheck(LabChecks& checks, const std::string& name, std::vector<ShadowCase> cases,
                    SourcePlace where = SourcePlace::here()) {
    std::vector<protocol::Call> calls;
    for (const ShadowCase& c : cases) calls.push_back(shadowCall(c.scene, c.point));
    checks.add({name, calls, [cases](const auto& out, Judge& judge) {
                    const auto answer = [](bool shadow) { return tr(shadow ? "what.lab6.shadow" : "what.lab6.lit"); };
                    for (std::size_t k = 0; k < cases.size(); ++k) {
                        const bool got = probes::inShadow.answer(out[k]);
                        judge.expectTrue(cases[k].what, got == cases[k].inShadow, answer(cases[k].inShadow),
                                         answer(got), cases[k].hint);
                    }
                }},
                where);
}

// A point of the ground y = 0 with a sphere halfway to its light: in shadow. The companion of the
// checks whose cases are lit.
ShadowCase shadowedCompanion() {
    return {tr("what.lab6.below_sphere"),
            {{{0., 2., 5.}, 0.5}, {{0., 0., 0.}, {0., 1., 0.}}, {{0., 4., 5.}}},
            {0., 0., 5.},
            true,
            tr("hint.lab6.companion_shadow")};
}

// The same ground with the sphere beside the segment to the light: lit. The companion of the checks
// whose cases are in shadow.
ShadowCase litCompanion() {
    return {tr("what.lab6.beside_sphere"),
            {{{2.5, 2., 3.}, 1.}, {{0., 0., 0.}, {0., 1., 0.}}, {{0., 5., 3.}}},
            {0., 0., 3.},
            false,
            tr("hint.lab6.companion_lit")};
}

// A unit direction drawn in the half-space above the ground, at least about 25 degrees above it.
glm::dvec3 upwards(CaseRandom& random) {
    glm::dvec3 d = random.unitVector();
    d.y = std::abs(d.y) + 0.5;
    return glm::normalize(d);
}

void addShadowChecks(LabChecks& checks, CaseRandom& random) {
    const Plane ground{{0., 0., 0.}, {0., 1., 0.}};
    {
        // A sphere behind the point, opposite the light: a shadow ray cast away from the light meets it.
        const glm::dvec3 point = CaseRandom::asFloat(random.vec3(-3., 3.)), l = random.unitVector();
        const double distance = random.uniform(3., 6.);
        const Sphere behind{CaseRandom::asFloat(point - 2. * l), CaseRandom::asFloat(random.uniform(0.5, 1.))};
        const Light light{CaseRandom::asFloat(point + distance * l)};
        addShadowCheck(
            checks, "lit",
            {{tr("what.lab6.ground_lit"), {{{5., 1., 5.}, 1.}, ground, {{0., 4., 3.}}}, {1., 0., 2.}, false,
              tr("hint.lab6.lit")},
             {tr("what.lab6.sphere_behind", {{"point", show(glm::dvec3(0.))}, {"sphere", describe({{0., -2., 0.}, 1.})}}),
              {{{0., -2., 0.}, 1.}, {}, {{0., 3., 0.}}},
              glm::dvec3(0.),
              false,
              tr("hint.lab6.towards_light")},
             {tr("what.lab6.sphere_behind", {{"point", show(point)}, {"sphere", describe(behind)}}),
              {behind, {}, light},
              point,
              false,
              tr("hint.lab6.towards_light")},
             shadowedCompanion()});
    }
    {
        const glm::dvec3 point = CaseRandom::asFloat(glm::dvec3(random.uniform(-3., 3.), 0., random.uniform(-3., 3.)));
        const glm::dvec3 l = upwards(random);
        const double distance = random.uniform(4., 8.);
        const Sphere between{CaseRandom::asFloat(point + l * (distance * random.uniform(0.35, 0.65))),
                             CaseRandom::asFloat(random.uniform(0.3, 0.8))};
        const Light light{CaseRandom::asFloat(point + distance * l)};
        addShadowCheck(checks, "occluder",
                       {{tr("what.lab6.ground_under", {{"point", show(glm::dvec3(0., 0., 3.))}}),
                         {{{0., 2., 3.}, 1.}, ground, {{0., 5., 3.}}},
                         {0., 0., 3.},
                         true,
                         tr("hint.lab6.shadow")},
                        {tr("what.lab6.ground_under_drawn", {{"point", show(point)}, {"sphere", describe(between)}}),
                         {between, ground, light},
                         point,
                         true,
                         tr("hint.lab6.shadow")},
                        litCompanion()});
    }
    {
        // Points a little under their surface, as the rounding of a hit point leaves half of them
        // (exaggerated: 1e-5 where a float hit point is off by about 1e-6): a shadow ray from t = 0
        // crosses the surface at once.
        constexpr double kUnder = 1e-5;
        const Sphere sphere{{0., 0., 3.}, 1.};
        const glm::dvec3 n = glm::normalize(glm::dvec3(0.3, 1., -0.4));
        const glm::dvec3 normal = random.unitVector();
        const glm::dvec3 across = glm::normalize(glm::cross(normal, random.unitVector()));
        const Plane drawn{CaseRandom::asFloat(random.vec3(-3., 3.)), CaseRandom::asFloat(normal)};
        const glm::dvec3 point = CaseRandom::asFloat(drawn.point + across * random.uniform(0.5, 2.) - kUnder * normal);
        const Light light{CaseRandom::asFloat(point + random.uniform(3., 6.) * glm::normalize(normal + 0.5 * across))};
        addShadowCheck(
            checks, "no_acne",
            {{tr("what.lab6.under_ground", {{"depth", show(kUnder)}}), {{}, ground, {{0., 4., 2.}}},
              {0.3, -kUnder, 2.1}, false, tr("hint.lab6.acne")},
             {tr("what.lab6.under_sphere", {{"depth", show(kUnder)}, {"sphere", describe(sphere)}}),
              {sphere, {}, {sphere.centre + 5. * n}},
              CaseRandom::asFloat(sphere.centre + (1. - kUnder) * n),
              false,
              tr("hint.lab6.acne_sphere")},
             {tr("what.lab6.under_plane",
                 {{"depth", show(kUnder)}, {"point", show(drawn.point)}, {"normal", show(drawn.normal)}}),
              {{}, drawn, light},
              point,
              false,
              tr("hint.lab6.acne")},
             shadowedCompanion()});
    }
    {
        const glm::dvec3 point = CaseRandom::asFloat(glm::dvec3(random.uniform(-3., 3.), 0., random.uniform(-3., 3.)));
        const glm::dvec3 l = upwards(random);
        const double distance = random.uniform(2., 4.), radius = random.uniform(0.5, 1.);
        const Sphere beyond{CaseRandom::asFloat(point + l * (distance + radius + random.uniform(0.5, 2.))),
                            CaseRandom::asFloat(radius)};
        const Light light{CaseRandom::asFloat(point + distance * l)};
        addShadowCheck(checks, "beyond_light",
                       {{tr("what.lab6.beyond", {{"point", show(glm::dvec3(0., 0., 3.))}}),
                         {{{0., 4., 3.}, 1.}, ground, {{0., 2., 3.}}},
                         {0., 0., 3.},
                         false,
                         tr("hint.lab6.beyond")},
                        {tr("what.lab6.beyond_drawn", {{"point", show(point)}, {"sphere", describe(beyond)}}),
                         {beyond, ground, light},
                         point,
                         false,
                         tr("hint.lab6.beyond")},
                        shadowedCompanion()});
    }
}

// One Li call: its scene (the objects' colours, the light's intensity), the ray, and the hint for a
// wrong colour.
struct LiCase {
    std::string what;
    ShadowScene scene;
    glm::dvec3 sphereColour, planeColour, background;
    Ray ray;
    std::string hint;
};

struct Shading {
    double ambient;
    bool shadows;
};

struct Hit {
    glm::dvec3 position, normal, colour;
    bool turned = false; // the normal was turned to face the ray
};

// The nearest hit of the case's ray, its normal turned towards the ray.
std::optional<Hit> nearestHit(const LiCase& c) {
    const std::optional<double> onSphere = crossing(c.scene.sphere, c.ray, 0.);
    const std::optional<double> onPlane = crossing(c.scene.plane, c.ray, 0.);
    if (!onSphere && !onPlane) return std::nullopt;
    Hit hit;
    if (onSphere && (!onPlane || *onSphere <= *onPlane)) {
        hit.position = c.ray.at(*onSphere);
        hit.normal = (hit.position - c.scene.sphere.centre) / c.scene.sphere.radius;
        hit.colour = c.sphereColour;
    } else {
        hit.position = c.ray.at(*onPlane);
        hit.normal = c.scene.plane.normal;
        hit.colour = c.planeColour;
    }
    hit.turned = glm::dot(hit.normal, c.ray.direction) > 0.;
    if (hit.turned) hit.normal = -hit.normal;
    return hit;
}

// Lambert's term as the handout writes it, or as a classic mistake does (the value it gives is the
// evidence that names it).
enum class Lambert { right, noFalloff, noPi };

// The colour Li must return at `hit`, the light counted when `lit` (or what `lambert` makes of it).
glm::dvec3 shade(const Shading& shading, const Light& light, const Hit& hit, bool lit, Lambert lambert = Lambert::right) {
    glm::dvec3 radiance = shading.ambient * hit.colour;
    const glm::dvec3 toLight = light.position - hit.position;
    const double distance = glm::length(toLight);
    const double cosine = glm::dot(hit.normal, toLight) / distance;
    const double falloff = lambert == Lambert::noFalloff ? 1. : distance * distance;
    const double reflection = lambert == Lambert::noPi ? 1. : std::numbers::inv_pi;
    if (cosine > 0. && lit) radiance += hit.colour * reflection * light.intensity * (cosine / falloff);
    return radiance;
}

// The classic mistakes of Li's formula at `hit`, each with the colour it gives.
std::vector<Suspect<glm::dvec3>> lambertSuspects(const Shading& shading, const Light& light, const Hit& hit, bool lit) {
    std::vector<Suspect<glm::dvec3>> suspects{
        {shade(shading, light, hit, lit, Lambert::noFalloff), tr("hint.lab6.inverse_square")},
        {shade(shading, light, hit, lit, Lambert::noPi), tr("hint.lab6.pi")}};
    if (hit.turned) { // the normal as computeNormal gives it, not turned towards the ray
        Hit unturned = hit;
        unturned.normal = -hit.normal;
        suspects.push_back({shade(shading, light, unturned, lit), tr("hint.lab6.facing")});
    }
    return suspects;
}

protocol::Call liCall(const Shading& shading, const LiCase& c) {
    const probes::ColouredObjects objects{c.scene.sphere, c.sphereColour, c.scene.plane, c.planeColour};
    return probes::pointLightLi(shading.ambient, shading.shadows, objects, c.scene.light, c.background, c.ray);
}

// Li calls the student's inShadow: with shadows on, the check also asks inShadow at each hit, so that
// a Li right for a wrong shadow answer is sent to inShadow, not told to fix its own formula.
void addLi(LabChecks& checks, const std::string& name, Shading shading, std::vector<LiCase> cases,
           SourcePlace where = SourcePlace::here()) {
    std::vector<protocol::Call> calls;
    for (const LiCase& c : cases) calls.push_back(liCall(shading, c));
    std::vector<std::size_t> shadowAt(cases.size(), 0); // the inShadow call of a hit, else 0
    if (shading.shadows)
        for (std::size_t k = 0; k < cases.size(); ++k)
            if (const std::optional<Hit> hit = nearestHit(cases[k])) {
                shadowAt[k] = calls.size();
                calls.push_back(shadowCall(cases[k].scene, CaseRandom::asFloat(hit->position)));
            }
    checks.add({name, calls, [shading, cases, shadowAt](const auto& out, Judge& judge) {
                    for (std::size_t k = 0; k < cases.size(); ++k) {
                        const LiCase& c = cases[k];
                        const glm::dvec3 got = probes::pointLightLi.answer(out[k]);
                        const std::optional<Hit> hit = nearestHit(c);
                        if (!hit) {
                            judge.expectNear(c.what, got, c.background, 1e-6, tr("hint.lab6.background"));
                            continue;
                        }
                        const bool lit = !shading.shadows || !occluded(c.scene, hit->position);
                        const glm::dvec3 expected = shade(shading, c.scene.light, *hit, lit);
                        std::string hint = c.hint;
                        std::vector<Suspect<glm::dvec3>> suspects = lambertSuspects(shading, c.scene.light, *hit, lit);
                        if (shadowAt[k] != 0) {
                            const bool theirShadow = probes::inShadow.answer(out[shadowAt[k]]);
                            const bool shadowedInstead = withinEach(got, shade(shading, c.scene.light, *hit, !lit), 1e-4);
                            if (theirShadow == lit && shadowedInstead) {
                                hint = tr("hint.lab6.li_through_in_shadow",
                                          {{"got", tr(theirShadow ? "what.lab6.shadow" : "what.lab6.lit")}});
                                suspects.clear();
                            } else if (lit && shadowedInstead) { // inShadow right at the exact point: Li's own, rounded, or no light term
                                hint = tr("hint.lab6.li_acne");
                                suspects.clear();
                            }
                        }
                        judge.expectNear(c.what, got, expected, 1e-4, hint, suspects);
                    }
                }},
                where);
}

void addLiChecks(LabChecks& checks, CaseRandom& random) {
    const Sphere sphere{{0., 0., 3.}, 1.};
    const Plane floor{{0., -1., 0.}, {0., 1., 0.}};
    const glm::dvec3 blue{0.2, 0.4, 0.9}, grey{0.8, 0.8, 0.8}, night{0.1, 0.1, 0.15};
    const Light above{{2., 3., 0.}, {10., 10., 10.}}, below{{2., -3., 0.}, {10., 10., 10.}};
    {
        // A drawn light and colour for the sphere seen along +z from a drawn point of the disc.
        const glm::dvec3 colour = CaseRandom::asFloat(random.vec3(0.2, 1.));
        const Light light{CaseRandom::asFloat(glm::dvec3(random.uniform(-4., 4.), random.uniform(1., 4.), random.uniform(-2., 1.))),
                          CaseRandom::asFloat(random.vec3(5., 20.))};
        const double angle = random.uniform(0., 2. * std::numbers::pi), offset = random.uniform(0., 0.7);
        const Ray drawn{CaseRandom::asFloat(glm::dvec3(offset * std::cos(angle), offset * std::sin(angle), 0.)), {0., 0., 1.}};
        const std::string lambert = tr("hint.lab6.lambert");
        addLi(checks, "lambert", {0.15, false},
              {{tr("what.lab6.li_front"), {sphere, floor, above}, blue, grey, night, {{0., 0., 0.}, {0., 0., 1.}}, lambert},
               {tr("what.lab6.li_floor"), {sphere, floor, above}, blue, grey, night, {{0., 0., 0.}, glm::normalize(glm::dvec3(0.5, -1., 2.))},
                lambert},
               {tr("what.lab6.li_away"), {sphere, floor, above}, blue, grey, night, {{0., 0., 6.}, {0., 0., -1.}},
                tr("hint.lab6.behind_surface")},
               {tr("what.lab6.li_from_below"), {sphere, floor, below}, blue, grey, night, {{0., -3., 1.5}, {0., 1., 0.}},
                tr("hint.lab6.from_below")},
               {tr("what.lab6.li_miss"), {sphere, floor, above}, blue, grey, night, {{0., 0., 0.}, glm::normalize(glm::dvec3(0., 1., 0.2))},
                tr("hint.lab6.background")},
               {tr("what.lab6.li_drawn", {{"origin", show(drawn.origin)}, {"colour", show(colour)}, {"light", show(light.position)}}),
                {sphere, floor, light}, colour, grey, night, drawn, lambert}});
    }
    {
        // The ground y = 0 under a sphere floating between it and the light; the camera's rays from
        // (0, 2, -1) pass under the sphere.
        const Sphere floating{{0., 1.5, 4.}, 0.7};
        const Plane ground{{0., 0., 0.}, {0., 1., 0.}};
        const Light light{{0., 5., 4.}, {20., 20., 20.}};
        const glm::dvec3 red{0.9, 0.3, 0.2}, eye{0., 2., -1.};
        const auto towards = [&eye](const glm::dvec3& target) { return Ray{eye, glm::normalize(target - eye)}; };
        const double angle = random.uniform(0., 2. * std::numbers::pi), offset = random.uniform(0., 0.4);
        const glm::dvec3 shadowed = CaseRandom::asFloat(glm::dvec3(offset * std::cos(angle), 0., 4. + offset * std::sin(angle)));
        addLi(checks, "ambient_in_shadow", {0.1, true},
              {{tr("what.lab6.li_in_shadow", {{"point", show(glm::dvec3(0.2, 0., 4.1))}}), {floating, ground, light}, red, grey,
                night, towards({0.2, 0., 4.1}), tr("hint.lab6.ambient_only")},
               {tr("what.lab6.li_in_shadow", {{"point", show(shadowed)}}), {floating, ground, light}, red, grey, night,
                towards(shadowed), tr("hint.lab6.ambient_only")},
               {tr("what.lab6.li_lit_ground", {{"point", show(glm::dvec3(2.5, 0., 4.5))}}), {floating, ground, light}, red, grey,
                night, towards({2.5, 0., 4.5}), tr("hint.lab6.lambert")},
               {tr("what.lab6.li_sphere_top"), {floating, ground, light}, red, grey, night, {{0., 5., 4.5}, glm::normalize(glm::dvec3(0., -1., -0.2))},
                tr("hint.lab6.lambert")}});
    }
}

// The draws happen in this order: the shadow test's cases, then Li's.
void addChecks(LabChecks& checks, CaseRandom& random) {
    addShadowChecks(checks, random);
    addLiChecks(checks, random);
}

} // namespace

RAYLAB_REGISTER_CHECKS(addChecks);

} // namespace raylab::grader
