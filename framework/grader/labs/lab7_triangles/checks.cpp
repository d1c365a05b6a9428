// Lab 7's function checks: where a ray crosses a triangle (inside, outside but within the
// parallelogram of its two edges, parallel to it, before tMin or past tMax), on fixed triangles and on
// triangles drawn at grading time, and its normal.
#include "answers.h"
#include "grader/judge/checks/checks.h"
#include "probes.h"

#include "src/messages.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace raylab::grader {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

using probes::Ray;
using probes::Triangle;

// The square of the quad figure, lower half: its normal is (0, 0, -1), towards the default camera.
const Triangle kTriangle{{-1., -1., 3.}, {-1., 1., 3.}, {1., -1., 3.}};

// The ray from `origin` through the point (u, v) of the triangle: it reaches it at t = 1.
Ray through(const glm::dvec3& origin, const Triangle& t, double u, double v) {
    return {origin, CaseRandom::asFloat(t.at(u, v) - origin)};
}

// One intersect call and what it must give: a hit at t, or a miss (t < 0).
struct Case {
    std::string what;
    Triangle triangle;
    Ray ray;
    double tMin = 0., tMax = kInf;
    double t = -1.; // < 0: a miss
    std::string hint;
    // Only a hit is asked: the companion of the misses, so that `return false` earns none of them.
    bool anyHit = false;
    double toleranceFactor = 1.; // times tolerance(t), for a grazing ray (drawnCase)
};

protocol::Call call(const Case& c) { return probes::triangleIntersect(c.triangle, c.ray, c.tMin, c.tMax); }

using lab7::Crossing;
std::optional<Crossing> crossing(const Triangle& tri, const Ray& r) { return lab7::crossing(tri.a, tri.b, tri.c, r.origin, r.direction); }

// The t a case's outputs must show, relative to its size: 1e-4 of the distance, at least 1e-5.
double tolerance(double t) { return std::max(1e-5, 1e-4 * std::abs(t)); }

void judgeCase(Judge& judge, const Case& c, const std::vector<double>& out) {
    const auto [found, t, position] = probes::triangleIntersect.answer(out);
    if (c.t >= 0.) {
        if (!found) {
            judge.fail(c.what, c.anyHit ? tr("what.lab7.a_hit") : tr("what.lab7.hit_at", {{"t", show(c.t)}}),
                       tr("what.lab7.no_hit"), c.hint);
            return;
        }
        if (c.anyHit) return;
        const double within = c.toleranceFactor * tolerance(c.t);
        if (judge.expectNear(c.what + ", t", t, c.t, within, c.hint))
            judge.expectNear(c.what + ", hit.position", position, c.ray.at(c.t), 2. * within, tr("hint.lab7.position"));
        return;
    }
    if (found) {
        // The evidence names the mistake: a NaN or infinite t comes from a division by det = 0; a hit
        // at the line's crossing with u + v > 1 comes from a missing u + v <= 1.
        const std::optional<Crossing> x = crossing(c.triangle, c.ray);
        std::string hint = c.hint;
        if (!std::isfinite(t)) hint = tr("hint.lab7.parallel");
        else if (x && x->u >= 0. && x->v >= 0. && !x->inside() && std::abs(t - x->t) <= tolerance(x->t))
            hint = tr("hint.lab7.u_plus_v");
        judge.fail(c.what, tr("what.lab7.no_hit"), tr("what.lab7.hit_at", {{"t", show(t)}}), hint);
    } else if (t != -7.) {
        judge.fail(tr("what.lab7.hit_record", {{"case", c.what}}), tr("what.lab7.left_alone"),
                   tr("what.lab7.t_changed", {{"t", show(t)}}), tr("hint.lab7.hit_record"));
    }
}

void addIntersect(LabChecks& checks, const std::string& id, std::vector<Case> cases, SourcePlace where = SourcePlace::here()) {
    std::vector<protocol::Call> calls;
    for (const Case& c : cases) calls.push_back(call(c));
    checks.add({id, calls, [cases](const auto& out, Judge& judge) {
                    for (std::size_t k = 0; k < cases.size(); ++k) judgeCase(judge, cases[k], out[k]);
                }},
               where);
}

// A triangle of corners drawn in a box in front of the origin, as floats: not too thin (its smallest
// height at least a tenth of its longest side) and seen from the origin at least 17 degrees from
// edge-on, so that most rays from near the origin that drawnCase aims at it are not grazing.
Triangle drawnTriangle(CaseRandom& random) {
    for (;;) {
        const Triangle t{CaseRandom::asFloat(random.vec3(-3., 3.) + glm::dvec3(0., 0., 6.)),
                         CaseRandom::asFloat(random.vec3(-3., 3.) + glm::dvec3(0., 0., 6.)),
                         CaseRandom::asFloat(random.vec3(-3., 3.) + glm::dvec3(0., 0., 6.))};
        const glm::dvec3 area = glm::cross(t.b - t.a, t.c - t.a);
        const double longest = std::max({glm::length(t.b - t.a), glm::length(t.c - t.b), glm::length(t.a - t.c)});
        const glm::dvec3 towards = glm::normalize(t.at(1. / 3., 1. / 3.));
        if (glm::length(area) >= 0.1 * longest * longest && std::abs(glm::dot(glm::normalize(area), towards)) >= 0.3) return t;
    }
}

std::string describe(const Triangle& t) {
    return tr("what.lab7.triangle", {{"a", show(t.a)}, {"b", show(t.b)}, {"c", show(t.c)}});
}

// A ray from a drawn origin near the camera through the point (u, v) of the triangle's plane, the
// least grazing of a few draws; its t is the crossing's, computed again from the float ray the child
// receives. A grazing ray's t is ill-conditioned in float, whoever computes it: the tolerance grows
// as the ray's angle with the plane shrinks below 11.5 degrees.
Case drawnCase(CaseRandom& random, const std::string& what, const Triangle& tri, double u, double v, const std::string& hint) {
    const glm::dvec3 n = lab7::normal(tri.a, tri.b, tri.c);
    Ray r{};
    double sine = -1.;
    for (int draw = 0; draw < 16 && sine < 0.2; ++draw) {
        const Ray candidate = through(CaseRandom::asFloat(random.vec3(-1., 1.)), tri, u, v);
        if (const double s = std::abs(glm::dot(glm::normalize(candidate.direction), n)); s > sine) r = candidate, sine = s;
    }
    const std::optional<Crossing> x = crossing(tri, r);
    const bool inside = x && x->inside() && x->t >= 0.;
    Case c{tr(what, {{"triangle", describe(tri)}, {"origin", show(r.origin)}}), tri, r, 0., kInf, inside ? x->t : -1., hint};
    c.toleranceFactor = std::max(1., 0.2 / sine);
    return c;
}

void addIntersectChecks(LabChecks& checks, CaseRandom& random) {
    const glm::dvec3 origin(0.);
    {
        const std::string hint = tr("hint.lab7.moller_trumbore");
        const Triangle drawn = drawnTriangle(random);
        const double u = random.uniform(0.1, 0.6), v = random.uniform(0.1, 0.8 - u);
        addIntersect(checks, "inside_hit",
                     {{tr("what.lab7.towards_fixed"), kTriangle, through(origin, kTriangle, 0.25, 0.25), 0., kInf, 1., hint},
                      drawnCase(random, "what.lab7.towards_inside", drawn, u, v, hint)});
    }
    {
        const std::string hint = tr("hint.lab7.outside");
        const Triangle drawn = drawnTriangle(random);
        const double u = random.uniform(0.3, 0.9), v = random.uniform(1.1 - u, 0.95);
        addIntersect(checks, "outside_misses",
                     {{tr("what.lab7.beyond_diagonal"), kTriangle, through(origin, kTriangle, 0.75, 0.75), 0., kInf, -1., hint},
                      {tr("what.lab7.beside_edge"), kTriangle, through(origin, kTriangle, -0.25, 0.5), 0., kInf, -1., hint},
                      drawnCase(random, "what.lab7.towards_outside", drawn, u, v, hint),
                      {tr("what.lab7.towards_fixed"), kTriangle, through(origin, kTriangle, 0.25, 0.25), 0., kInf, 1.,
                       tr("hint.lab7.miss_needs_hit"), true}});
    }
    {
        // det = e1 . (d x e2) is exactly 0 for these directions in float too: their z is 0, as the
        // triangle's edges'. From the plane's own points, u = 0 / 0 is NaN, which a test written as
        // `if (u < 0 || u > 1) return false` lets through.
        const std::string hint = tr("hint.lab7.parallel");
        const glm::dvec3 along = glm::dvec3(1., 1., 0.);
        addIntersect(checks, "parallel_misses",
                     {{tr("what.lab7.parallel_above"), kTriangle, {{0., 0., 2.}, along}, 0., kInf, -1., hint},
                      {tr("what.lab7.in_plane"), kTriangle, {{-0.5, -0.9, 3.}, along}, 0., kInf, -1., hint},
                      {tr("what.lab7.in_plane"), kTriangle, {{-2., -0.5, 3.}, {1., 0., 0.}}, 0., kInf, -1., hint},
                      {tr("what.lab7.towards_fixed"), kTriangle, through(origin, kTriangle, 0.25, 0.25), 0., kInf, 1.,
                       tr("hint.lab7.miss_needs_hit"), true}});
    }
    {
        const Ray ahead = through(origin, kTriangle, 0.25, 0.25); // t = 1
        const Ray behind{{-0.5, -0.5, 6.}, {0., 0., 1.}};       // the triangle 3 behind its origin
        addIntersect(checks, "triangle_t_bounds",
                     {{tr("what.lab7.behind"), kTriangle, behind, 0., kInf, -1., tr("hint.lab7.behind")},
                      {tr("what.lab7.t_max", {{"t", show(0.5)}}), kTriangle, ahead, 0., 0.5, -1., tr("hint.lab7.t_bounds")},
                      {tr("what.lab7.t_min", {{"t", show(1.5)}}), kTriangle, ahead, 1.5, kInf, -1., tr("hint.lab7.t_bounds")},
                      {tr("what.lab7.towards_fixed"), kTriangle, ahead, 0.5, 1.5, 1., tr("hint.lab7.t_bounds")}});
    }
    {
        const std::string hint = tr("hint.lab7.moller_trumbore");
        // First a fixed slanted triangle, towards its centroid (2/3, 2/3, 5) as floats (t near 1); then drawn ones.
        const Triangle slanted{{0., 0., 4.}, {2., 0., 6.}, {0., 2., 5.}};
        const Ray towardsCentroid = through(origin, slanted, 1. / 3., 1. / 3.);
        std::vector<Case> cases{{tr("what.lab7.towards_inside", {{"triangle", describe(slanted)}, {"origin", show(origin)}}),
                                 slanted, towardsCentroid, 0., kInf, crossing(slanted, towardsCentroid)->t, hint}};
        for (int k = 0; k < 3; ++k) {
            const Triangle drawn = drawnTriangle(random);
            const double u = random.uniform(0.05, 0.9), v = random.uniform(0.05, 0.95 - u);
            cases.push_back(drawnCase(random, "what.lab7.towards_inside", drawn, u, v, hint));
            const double outsideU = random.uniform(-0.8, 1.5), outsideV = random.uniform(1.05, 1.8) - outsideU;
            cases.push_back(drawnCase(random, "what.lab7.towards_outside", drawn, outsideU, outsideV, tr("hint.lab7.outside")));
        }
        addIntersect(checks, "drawn_triangles", cases);
    }
}

void addNormalCheck(LabChecks& checks, CaseRandom& random) {
    const Triangle drawn = drawnTriangle(random);
    const std::vector<Triangle> triangles{kTriangle, drawn};
    const std::vector<glm::dvec3> points{kTriangle.at(0.25, 0.25), CaseRandom::asFloat(drawn.at(0.3, 0.3))};
    std::vector<protocol::Call> calls;
    for (std::size_t k = 0; k < triangles.size(); ++k) calls.push_back(probes::triangleNormal(triangles[k], points[k]));
    checks.add({"triangle_normal", calls, [triangles, points](const auto& out, Judge& judge) {
                    for (std::size_t k = 0; k < triangles.size(); ++k) {
                        const Triangle& t = triangles[k];
                        const glm::dvec3 area = glm::cross(t.b - t.a, t.c - t.a), n = lab7::normal(t.a, t.b, t.c);
                        judge.expectNear(tr("what.lab7.normal_of", {{"triangle", describe(t)}}),
                                         probes::triangleNormal.answer(out[k]), n, 1e-5, tr("hint.lab7.normal"),
                                         {{-n, tr("hint.lab7.normal_flipped")}, {area, tr("hint.lab7.normal_unit")}});
                    }
                }});
}

// The draws happen in this order: intersect, then computeNormal.
void addChecks(LabChecks& checks, CaseRandom& random) {
    addIntersectChecks(checks, random);
    addNormalCheck(checks, random);
}

} // namespace

RAYLAB_REGISTER_CHECKS(addChecks);

} // namespace raylab::grader
