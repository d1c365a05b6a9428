// Lab 3's function checks: intersection distances of chosen rays (with the hard cases of
// docs/numerics.md that are fair to ask), normals and shading; each also on cases drawn at
// grading time.
#include "answers.h"
#include "grader/judge/checks/checks.h"
#include "probes.h"

#include "src/messages.h"

#include <glm/exponential.hpp>
#include <glm/geometric.hpp>

#include <cmath>
#include <limits>
#include <optional>
#include <utility>

namespace raylab::grader {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

using probes::Hit;
using probes::Ray;
using probes::Sphere;

const Sphere kSphere{{0., 0., 3.}, 1.};
const Ray kAlongZ{{0., 0., 0.}, {0., 0., 1.}}; // from the origin towards kSphere

// One intersect call and what it must give: a hit at t, or a miss (t < 0).
struct Case {
    std::string what;
    Sphere sphere;
    Ray ray;
    double tMin = 0., tMax = kInf;
    double t = -1.; // < 0: a miss
    double tolerance = 1e-5;
    std::string hint;
    // Only a hit is asked, wherever: the companion of a miss, so that a miss is earned only by an
    // intersect that also finds hits (a `return false` misses everything), without judging t twice.
    bool anyHit = false;
};

protocol::Call call(const Case& c) { return probes::intersect(c.sphere, c.ray, c.tMin, c.tMax); }

std::optional<lab3::Roots> roots(const Sphere& s, const Ray& r) { return lab3::roots(s.centre, s.radius, r.origin, r.direction); }
std::optional<double> nearestHit(const Sphere& s, const Ray& r) { return lab3::nearestHit(s.centre, s.radius, r.origin, r.direction); }


bool judgeCase(Judge& judge, const Case& c, const std::vector<double>& out) {
    const auto [found, t, position] = probes::intersect.answer(out);
    if (c.t >= 0.) {
        if (!found) {
            judge.fail(c.what, c.anyHit ? tr("what.lab3.a_hit") : tr("what.lab3.hit_at", {{"t", show(c.t)}}),
                       tr("what.lab3.no_hit"), c.hint);
            return false;
        }
        if (c.anyHit) return true;
        // The hint names the cause the outputs show: a far root where the near one was due is the root
        // choice, whatever the check is about.
        const auto line = roots(c.sphere, c.ray);
        const bool farRoot = line && std::abs(c.t - line->far) > c.tolerance &&
                             std::abs(t - line->far) <= c.tolerance && line->near >= c.tMin;
        return judge.expectNear(c.what + ", t", t, c.t, c.tolerance, farRoot ? tr("hint.lab3.far_root") : c.hint) &&
               judge.expectNear(c.what + ", hit.position", position, c.ray.at(c.t), c.tolerance * 2.,
                                tr("hint.lab3.position"));
    }
    if (found)
        judge.fail(c.what, tr("what.lab3.no_hit"), tr("what.lab3.hit_at", {{"t", show(t)}}), c.hint);
    else if (t != -7.)
        judge.fail(tr("what.lab3.hit_record", {{"case", c.what}}), tr("what.lab3.left_alone"),
                   tr("what.lab3.t_changed", {{"t", show(t)}}), tr("hint.lab3.hit_record"));
    return !found;
}

void addIntersect(LabChecks& checks, const std::string& name, std::vector<Case> cases,
                  SourcePlace where = SourcePlace::here()) {
    std::vector<protocol::Call> calls;
    for (const Case& c : cases)
        calls.push_back(call(c));
    checks.add({name, calls, [cases](const auto& out, Judge& judge) {
                   for (std::size_t k = 0; k < cases.size(); ++k)
                       judgeCase(judge, cases[k], out[k]);
               }},
               where);
}

// A far sphere's cases, judged after a near sphere confirms the root choice: the discriminant's
// cancellation is blamed only when the near root is taken where it should be, and the hint says
// what the near sphere showed otherwise.
void addFarIntersect(LabChecks& checks, const std::string& name, std::vector<Case> cases,
                     SourcePlace where = SourcePlace::here()) {
    const Case nearSphere{"", kSphere, kAlongZ, 0., kInf, 2., 1e-5, ""};
    std::vector<protocol::Call> calls{call(nearSphere)};
    for (const Case& c : cases)
        calls.push_back(call(c));
    checks.add({name, calls, [cases](const auto& out, Judge& judge) {
                   const auto [found, t, position] = probes::intersect.answer(out[0]);
                   const bool rootChoiceRight = found && std::abs(t - 2.) <= 1e-5;
                   for (std::size_t k = 0; k < cases.size(); ++k) {
                       Case c = cases[k];
                       if (!rootChoiceRight)
                           c.hint = tr("hint.lab3.near_first", {{"got", found ? "t = " + show(t) : tr("what.lab3.no_hit")}}) +
                                    (found && std::abs(t - 4.) <= 1e-5 ? tr("hint.lab3.and_far_root") : "");
                       judgeCase(judge, c, out[k + 1]);
                   }
               }},
               where);
}

Sphere drawnSphere(CaseRandom& random) {
    return {CaseRandom::asFloat(random.vec3(-5., 5.)), CaseRandom::asFloat(random.uniform(0.5, 2.))};
}

std::string describe(const Sphere& s) {
    return tr("what.lab3.sphere", {{"centre", show(s.centre)}, {"radius", show(s.radius)}});
}

// A ray from outside a drawn sphere towards a point of its disc at `offset` radii from its centre line.
Ray rayTowards(CaseRandom& random, const Sphere& s, double offset) {
    const glm::dvec3 axis = random.unitVector();
    glm::dvec3 side = glm::normalize(glm::cross(axis, random.unitVector()));
    const glm::dvec3 origin = CaseRandom::asFloat(s.centre - axis * (s.radius * random.uniform(3., 8.)));
    const glm::dvec3 aim = s.centre + side * (offset * s.radius);
    return {origin, CaseRandom::asFloat(glm::normalize(aim - origin))};
}

using lab3::kCosine;
using lab3::kFlat;
using lab3::kPlaceholder;

const glm::dvec3 kBlue{0., 0., 1.}, kGrey{0.5, 0.5, 0.5};

struct LiCase {
    std::string what;
    int shading;
    Sphere sphere;
    glm::dvec3 colour, background;
    Ray ray;
    double tolerance;
    std::string hint;
};

// The colour Li must return, in double.
glm::dvec3 expectedLi(const LiCase& c) {
    const std::optional<double> t = nearestHit(c.sphere, c.ray);
    if (!t) return c.background;
    return lab3::shade(c.shading, c.colour, glm::normalize(c.ray.direction), (c.ray.at(*t) - c.sphere.centre) / c.sphere.radius);
}

// The classic mistakes of cosine shading, each with the colour it gives for the case: a gamma
// applied to the linear colour, and the cosine taken of the dot product (which is the cosine).
std::vector<Suspect<glm::dvec3>> shadingSuspects(const LiCase& c) {
    const std::optional<double> t = nearestHit(c.sphere, c.ray);
    if (c.shading != kCosine || !t) return {};
    const glm::dvec3 d = glm::normalize(c.ray.direction), n = (c.ray.at(*t) - c.sphere.centre) / c.sphere.radius;
    const double cosine = std::max(-glm::dot(d, n), 0.);
    return {{glm::pow(c.colour * cosine, glm::dvec3(1. / 2.2)), tr("hint.lab3.gamma")},
            {c.colour * std::max(std::cos(-glm::dot(d, n)), 0.), tr("hint.lab3.cos_of_dot")}};
}

// What Li returns for the hit (or miss) `intersect` gave: the background, or the shading at that hit
// with the true normal there.
glm::dvec3 liForHit(const LiCase& c, bool found, double t) {
    if (!found) return c.background;
    return lab3::shade(c.shading, c.colour, glm::normalize(c.ray.direction), glm::normalize(c.ray.at(t) - c.sphere.centre));
}

// Li calls the student's intersect, and cosine shading their computeNormal: the check also asks
// intersect for each ray, and computeNormal at the true hit, so that a Li right for a wrong hit or a
// wrong normal is sent to that function, not told to fix its own formula.
void addLi(LabChecks& checks, const std::string& name, std::vector<LiCase> cases,
           SourcePlace where = SourcePlace::here()) {
    std::vector<protocol::Call> calls;
    for (const LiCase& c : cases)
        calls.push_back(probes::li(c.shading, c.sphere, c.colour, c.background, c.ray));
    const std::size_t hitsAt = calls.size(); // intersect's answer for case k is at hitsAt + k
    for (const LiCase& c : cases) calls.push_back(call(Case{"", c.sphere, c.ray, 0., kInf, -1., 1e-5, ""}));
    std::vector<std::size_t> normalAt(cases.size(), 0); // the normal call of a cosine hit, else 0
    for (std::size_t k = 0; k < cases.size(); ++k)
        if (const std::optional<double> t = nearestHit(cases[k].sphere, cases[k].ray); t && cases[k].shading == kCosine) {
            normalAt[k] = calls.size();
            calls.push_back(probes::computeNormal(cases[k].sphere, CaseRandom::asFloat(cases[k].ray.at(*t))));
        }
    checks.add({name, calls, [cases, normalAt, hitsAt](const auto& out, Judge& judge) {
                   for (std::size_t k = 0; k < cases.size(); ++k) {
                       const LiCase& c = cases[k];
                       const glm::dvec3 got = probes::li.answer(out[k]);
                       std::string hint = c.hint;
                       std::vector<Suspect<glm::dvec3>> suspects = shadingSuspects(c);
                       const auto [found, t, position] = probes::intersect.answer(out[hitsAt + k]);
                       const std::optional<double> trueT = nearestHit(c.sphere, c.ray);
                       const bool hitWrong = found != trueT.has_value() ||
                                             (found && std::abs(t - *trueT) > 1e-4 * std::max(1., *trueT));
                       if (hitWrong && withinEach(got, liForHit(c, found, t), c.tolerance)) {
                           hint = tr("hint.lab3.li_through_intersect",
                                     {{"got", found ? "t = " + show(t) : tr("what.lab3.no_hit")},
                                      {"expected", trueT ? "t = " + show(*trueT) : tr("what.lab3.no_hit")}});
                           suspects.clear();
                       } else if (normalAt[k] != 0) {
                           const glm::dvec3 n = probes::computeNormal.answer(out[normalAt[k]]),
                                            d = glm::normalize(c.ray.direction);
                           const glm::dvec3 forTheirNormal = c.colour * std::max(-glm::dot(d, n), 0.);
                           if (withinEach(got, forTheirNormal, c.tolerance)) {
                               hint = tr("hint.lab3.cosine_own_normal");
                               suspects.clear();
                           }
                       }
                       judge.expectNear(c.what, got, expectedLi(c), c.tolerance, hint, suspects);
                   }
               }},
               where);
}

void addIntersectChecks(LabChecks& checks, CaseRandom& random) {
    {
        const std::string hint = tr("hint.lab3.quadratic");
        const Sphere s = drawnSphere(random);
        const Ray r = rayTowards(random, s, 0.);
        addIntersect(checks, "near_side",
                     {{tr("what.lab3.origin_along_z"), kSphere, kAlongZ, 0., kInf, 2., 1e-5, hint},
                      {tr("what.lab3.towards_centre", {{"origin", show(r.origin)}, {"sphere", describe(s)}}), s, r, 0., kInf,
                       *nearestHit(s, r), 1e-4, hint}});
    }
    {
        const std::string hint = tr("hint.lab3.miss");
        const Sphere s = drawnSphere(random);
        const Ray r = rayTowards(random, s, random.uniform(1.1, 3.));
        const Ray atCentre{r.origin, CaseRandom::asFloat(glm::normalize(s.centre - r.origin))};
        const std::string hitHint = tr("hint.lab3.miss_needs_hit");
        addIntersect(
            checks, "beside_misses",
            {{tr("what.lab3.beside_fixed"), kSphere, {{2., 0., 0.}, {0., 0., 1.}}, 0., kInf, -1., 0., hint},
             {tr("what.lab3.beside", {{"origin", show(r.origin)}, {"sphere", describe(s)}}), s, r, 0., kInf, -1., 0., hint},
             {tr("what.lab3.through_fixed"), kSphere, {{0.5, 0., 0.}, {0., 0., 1.}}, 0., kInf, 0., 0., hitHint, true},
             {tr("what.lab3.towards_centre", {{"origin", show(atCentre.origin)}, {"sphere", describe(s)}}), s, atCentre, 0.,
              kInf, 0., 0., hitHint, true}});
    }
    {
        // Integer coordinates: the tangent's discriminant is exactly 0 in float too.
        const std::string hint = tr("hint.lab3.tangent");
        const Sphere s{{double(random.integer(-5, 5)), double(random.integer(-5, 5)), double(random.integer(-5, 5))},
                       double(random.integer(1, 3))};
        const double k = random.integer(int(s.radius) + 1, 10);
        const Ray r{s.centre + glm::dvec3(s.radius, 0., -k), {0., 0., 1.}};
        addIntersect(checks, "tangent",
                     {{tr("what.lab3.tangent_fixed"),
                       kSphere,
                       {{1., 0., 0.}, {0., 0., 1.}},
                       0.,
                       kInf,
                       3.,
                       1e-4,
                       hint},
                      {tr("what.lab3.tangent", {{"origin", show(r.origin)}, {"sphere", describe(s)}}), s, r, 0., kInf, k,
                       1e-4, hint}});
    }
    {
        const std::string hint = tr("hint.lab3.inside");
        const Sphere s = drawnSphere(random);
        const Ray r{s.centre, CaseRandom::asFloat(random.unitVector())};
        addIntersect(checks, "from_inside",
                     {{tr("what.lab3.inside_fixed"),
                       kSphere,
                       {{0., 0., 3.}, {0., 0., 1.}},
                       0.,
                       kInf,
                       1.,
                       1e-5,
                       hint},
                      {tr("what.lab3.inside", {{"sphere", describe(s)}, {"direction", show(r.direction)}}), s, r, 0., kInf,
                       *nearestHit(s, r), 1e-5, hint}});
    }
    {
        const std::string hint = tr("hint.lab3.behind"), hitHint = tr("hint.lab3.miss_needs_hit");
        const Sphere s = drawnSphere(random);
        const glm::dvec3 d = CaseRandom::asFloat(random.unitVector());
        const Ray r{CaseRandom::asFloat(s.centre + d * (s.radius * random.uniform(1.5, 5.))), d};
        addIntersect(checks, "behind",
                     {{tr("what.lab3.behind_fixed"),
                       kSphere,
                       {{0., 0., 5.}, {0., 0., 1.}},
                       0.,
                       kInf,
                       -1.,
                       0.,
                       hint},
                      {tr("what.lab3.behind", {{"origin", show(r.origin)}, {"direction", show(d)}, {"sphere", describe(s)}}), s, r,
                       0., kInf, -1., 0., hint},
                      // The same rays turned round see the sphere ahead: a miss is earned only with these hits.
                      {tr("what.lab3.ahead_fixed"), kSphere, {{0., 0., 5.}, {0., 0., -1.}}, 0., kInf, 0., 0., hitHint, true},
                      {tr("what.lab3.ahead", {{"origin", show(r.origin)}, {"direction", show(-d)}, {"sphere", describe(s)}}), s,
                       {r.origin, -d}, 0., kInf, 0., 0., hitHint, true}});
    }
    addIntersect(
        checks, "t_bounds",
        {{tr("what.lab3.t_max", {{"t", show(1.5)}}), kSphere, kAlongZ, 0., 1.5, -1., 0., tr("hint.lab3.t_max")},
         {tr("what.lab3.t_min", {{"t", show(2.5)}}), kSphere, kAlongZ, 2.5, kInf, 4., 1e-5, tr("hint.lab3.t_min")}});
    {
        const std::string hint = tr("hint.lab3.not_unit");
        const double scale = CaseRandom::asFloat(random.uniform(0.3, 5.));
        addIntersect(
            checks, "not_unit_direction",
            {{tr("what.lab3.origin_along", {{"direction", show(glm::dvec3(0., 0., 2.))}}), kSphere, {{0., 0., 0.}, {0., 0., 2.}}, 0., kInf, 1., 1e-5, hint},
             {tr("what.lab3.origin_along", {{"direction", show(glm::dvec3(0., 0., scale))}}),
              kSphere,
              {{0., 0., 0.}, {0., 0., scale}},
              0.,
              kInf,
              2. / scale,
              1e-5,
              hint}});
    }
    {
        const Sphere far{{0., 0., 1000.}, 1.};
        const double offset = CaseRandom::asFloat(random.uniform(0., 0.9));
        const std::string hint = tr("hint.lab3.far_1000");
        addFarIntersect(checks, "far_1000",
                     {{tr("what.lab3.at_radius", {{"offset", show(0.5)}}),
                       far,
                       {{0.5, 0., 0.}, {0., 0., 1.}},
                       0.,
                       kInf,
                       1000. - std::sqrt(0.75),
                       2e-3,
                       hint},
                      {tr("what.lab3.at_radius", {{"offset", show(offset)}}),
                       far,
                       {{offset, 0., 0.}, {0., 0., 1.}},
                       0.,
                       kInf,
                       1000. - std::sqrt(1. - offset * offset),
                       2e-3,
                       hint},
                      {tr("what.lab3.at_radii", {{"offset", show(1.5)}}),
                       far,
                       {{1.5, 0., 0.}, {0., 0., 1.}},
                       0.,
                       kInf,
                       -1.,
                       0.,
                       tr("hint.lab3.far_miss")}});
    }
    {
        const Sphere far{{0., 0., 10000.}, 1.};
        const std::string hint = tr("hint.lab3.far_10000");
        addFarIntersect(
            checks, "far_10000",
            {{tr("what.lab3.at_radii", {{"offset", show(1.1)}}), far, {{1.1, 0., 0.}, {0., 0., 1.}}, 0., kInf, -1., 0., hint},
             {tr("what.lab3.at_radius", {{"offset", show(0.9)}}),
              far,
              {{0.9, 0., 0.}, {0., 0., 1.}},
              0.,
              kInf,
              10000. - std::sqrt(0.19),
              0.02,
              hint}});
    }
}

void addNormalCheck(LabChecks& checks, CaseRandom& random) {
    const Sphere big{{1., 2., 3.}, 2.}, drawn = drawnSphere(random);
    const glm::dvec3 n = random.unitVector(), point = CaseRandom::asFloat(drawn.centre + n * drawn.radius);
    const std::vector<std::pair<Sphere, glm::dvec3>> cases{
        {kSphere, {0., 0., 2.}}, {big, {1., 2., 5.}}, {drawn, point}};
    std::vector<protocol::Call> calls;
    for (const auto& [s, p] : cases) calls.push_back(probes::computeNormal(s, p));
    // The hint names what the answer shows: a length other than 1, or the inward direction.
    auto hint = [](const glm::dvec3& got, const glm::dvec3& expected) {
        if (!(std::abs(glm::length(got) - 1.) <= 1e-3)) return tr("hint.lab3.normal_unit");
        if (glm::dot(got, expected) < 0.) return tr("hint.lab3.normal_outwards");
        return tr("hint.lab3.normal");
    };
    checks.add(
        {"normal", calls, [cases, hint](const auto& out, Judge& judge) {
      const std::string what[] = {tr("what.lab3.normal_at", {{"point", show(glm::dvec3(0., 0., 2.))}}),
                                  tr("what.lab3.normal_radius_2", {{"point", show(glm::dvec3(1., 2., 5.))}}),
                                  tr("what.lab3.normal_of", {{"point", show(cases[2].second)}, {"sphere", describe(cases[2].first)}})};
      for (std::size_t k = 0; k < cases.size(); ++k) {
          const auto& [s, p] = cases[k];
          const glm::dvec3 got = probes::computeNormal.answer(out[k]), expected = (p - s.centre) / s.radius;
          judge.expectNear(what[k], got, expected, k < 2 ? 1e-6 : 1e-5, hint(got, expected));
      }
         }});
}

void addLiChecks(LabChecks& checks, CaseRandom& random) {
    const Sphere drawn = drawnSphere(random);
    const glm::dvec3 colour = CaseRandom::asFloat(random.vec3(0.1, 1.)),
                     background = CaseRandom::asFloat(random.vec3(0., 1.));
    const Ray hitting = rayTowards(random, drawn, random.uniform(0., 0.8)),
              missing = rayTowards(random, drawn, random.uniform(1.2, 3.));
    const std::string drawnScene = tr("what.lab3.scene", {{"sphere", describe(drawn)}, {"colour", show(colour)}});
    {
        const std::string hitHint = tr("hint.lab3.flat_hit");
        const std::string missHint = tr("hint.lab3.flat_miss");
        addLi(checks, "flat",
              {{tr("what.lab3.flat_z"), kFlat, kSphere, kBlue, kGrey, kAlongZ, 1e-6, hitHint},
               {tr("what.lab3.flat_x"),
                kFlat,
                kSphere,
                kBlue,
                kGrey,
                {{0., 0., 0.}, {1., 0., 0.}},
                1e-6,
                missHint},
               {tr("what.lab3.flat_hits", {{"scene", drawnScene}}), kFlat, drawn, colour, background, hitting, 1e-6, hitHint},
               {tr("what.lab3.flat_misses", {{"scene", drawnScene}}), kFlat, drawn, colour, background, missing, 1e-6, missHint}});
    }
    {
        const std::string hint = tr("hint.lab3.cosine");
        // From (0.6, 0, 0) along +z: the hit is (0.6, 0, 2.2), n = (0.6, 0, -0.8), -d.n = 0.8.
        addLi(checks, "cosine",
              {{tr("what.lab3.cosine_z"), kCosine, kSphere, kBlue, kGrey, kAlongZ, 1e-5, tr("hint.lab3.cosine_facing")},
               {tr("what.lab3.cosine_from", {{"origin", show(glm::dvec3(0.6, 0., 0.))}}),
                kCosine,
                kSphere,
                kBlue,
                kGrey,
                {{0.6, 0., 0.}, {0., 0., 1.}},
                1e-5,
                hint},
               {tr("what.lab3.cosine_drawn", {{"origin", show(hitting.origin)}, {"scene", drawnScene}}), kCosine, drawn, colour, background, hitting,
                1e-4, hint}});
    }
    addLi(checks, "placeholder_normal",
          {{tr("what.lab3.placeholder_z"), kPlaceholder, kSphere, kBlue, kGrey, kAlongZ, 1e-5, tr("hint.lab3.placeholder")},
           {tr("what.lab3.placeholder_drawn", {{"origin", show(hitting.origin)}, {"scene", drawnScene}}), kPlaceholder,
            drawn, colour, background, hitting, 1e-5, tr("hint.lab3.placeholder")}});
}

// The draws happen in this order: intersect, computeNormal, then Li.
void addChecks(LabChecks& checks, CaseRandom& random) {
    addIntersectChecks(checks, random);
    addNormalCheck(checks, random);
    addLiChecks(checks, random);
}

} // namespace

RAYLAB_REGISTER_CHECKS(addChecks);

} // namespace raylab::grader
