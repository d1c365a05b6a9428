// The intersection measurements: hit/miss, t and normals of each formula against a long double
// reference, and their cost.
#include "numerics_study.h"
#include "sphere_formulas.h"

#include "raylab/random.h"
#include "src/render_space.h"
#include "raylab/sphere_geometry.h"
#include "raylab/todo.h"

#include <algorithm>
#include <chrono>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace raylab::study {

namespace {

using LD = long double;
constexpr float kInf = std::numeric_limits<float>::infinity();

// The sphere lies along u from the ray origin; e1, e2 complete an orthonormal frame (exact decimals).
constexpr double kU[3] = {0.36, 0.48, 0.8};
constexpr double kE1[3] = {0.8, -0.6, 0.};
constexpr double kE2[3] = {0.48, 0.64, -0.6};

// Rays from `origin` aimed at points spread uniformly over a disc of radius spread * radius around
// the sphere's centre, across the line of sight: the rays that come near the sphere. Everything is
// rounded to float once, as a scene file and a camera would give it; the reference then works
// on those float values exactly.
struct RaySet {
    glm::vec3 origin, centre;
    float radius;
    std::vector<glm::vec3> directions;
};

RaySet aimedRays(const glm::dvec3& origin, double distance, double radius, double spread, int count) {
    RaySet set;
    set.origin = glm::vec3(origin);
    const glm::dvec3 u(kU[0], kU[1], kU[2]), e1(kE1[0], kE1[1], kE1[2]), e2(kE2[0], kE2[1], kE2[2]);
    const glm::dvec3 centre = origin + distance * u;
    set.centre = glm::vec3(centre);
    set.radius = float(radius);
    Pcg32 rng(7, std::uint64_t(distance * 1000. + radius));
    set.directions.reserve(std::size_t(count));
    for (int k = 0; k < count; ++k) {
        const double rho = spread * radius * std::sqrt(double(rng.nextFloat()));
        const double phi = 6.283185307179586 * double(rng.nextFloat());
        const glm::dvec3 aim = glm::dvec3(set.centre) + rho * (std::cos(phi) * e1 + std::sin(phi) * e2);
        const glm::dvec3 d = aim - glm::dvec3(set.origin);
        set.directions.push_back(glm::vec3(d / std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z)));
    }
    return set;
}

// One formula's answer for one ray, in long double for comparison.
struct Answer {
    bool hit = false;
    LD t = 0;
    V3<LD> normal;
};

using Method = std::function<Answer(const RaySet&, const glm::vec3& direction)>;

template <class T, bool Stable>
Answer formula(const RaySet& s, const glm::vec3& direction) {
    const V3<T> o = V3<T>::from(s.origin), d = V3<T>::from(direction), c = V3<T>::from(s.centre);
    const SphereHit<T> h = Stable ? stableIntersect(o, d, c, T(s.radius), T(0), T(kInf))
                                  : textbookIntersect(o, d, c, T(s.radius), T(0), T(kInf));
    if (!h.hit) return {};
    const V3<T> n = normalAt(o, d, c, T(s.radius), h.t);
    return {true, LD(h.t), {LD(n.x), LD(n.y), LD(n.z)}};
}

// The lab code of this build: SphereGeometry::intersect, then computeNormal at hit.position.
Answer labCode(const RaySet& s, const glm::vec3& direction) {
    const SphereGeometry sphere(s.centre, s.radius, Color(1.f));
    HitRecord hit;
    if (!sphere.intersect(Ray{s.origin, direction}, 0.f, kInf, hit)) return {};
    const glm::vec3 n = sphere.computeNormal(hit.position);
    return {true, LD(hit.t), V3<LD>::from(n)};
}

struct NamedMethod {
    const char* name;
    Method method;
};

const std::vector<NamedMethod>& methods() {
    static const std::vector<NamedMethod> all{
        {"textbook float", formula<float, false>},   {"stable float", formula<float, true>},
        {"textbook double", formula<double, false>}, {"stable double", formula<double, true>},
        {"lab code (float)", labCode},
    };
    return all;
}

struct Errors {
    std::int64_t misclassified = 0, rays = 0;
    double wrongBand = 0.; // the widest | |l| - r | / r of a misclassified ray: how near the silhouette
    std::vector<double> t, normal, shading; // shading: | max(-d.n, 0) - the exact one |
};

double median(std::vector<double> v) {
    if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
    return v[v.size() / 2];
}

double maximum(const std::vector<double>& v) {
    return v.empty() ? std::numeric_limits<double>::quiet_NaN() : *std::max_element(v.begin(), v.end());
}

Errors measure(const RaySet& set, const Method& method) {
    Errors e;
    for (const glm::vec3& d : set.directions) {
        const Answer truth = formula<LD, true>(set, d);
        const Answer got = method(set, d);
        ++e.rays;
        if (got.hit != truth.hit) {
            ++e.misclassified;
            const V3<LD> o = V3<LD>::from(set.origin), c = V3<LD>::from(set.centre);
            const LD l = closestDistance(o, V3<LD>::from(d), c);
            e.wrongBand = std::max(e.wrongBand, double(std::abs(l - LD(set.radius)) / LD(set.radius)));
        }
        if (!got.hit || !truth.hit) continue;
        e.t.push_back(double(std::abs(got.t - truth.t) / truth.t));
        e.normal.push_back(double(angleBetween(got.normal, truth.normal)));
        const V3<LD> dd = V3<LD>::from(d);
        e.shading.push_back(double(std::abs(std::max(-dot(dd, got.normal), LD(0)) - std::max(-dot(dd, truth.normal), LD(0)))));
    }
    return e;
}

// Runs a lab-code method; a stub not written yet gives a row that says so.
bool runLab(const std::function<void()>& body, std::string& note) {
    try {
        body();
        return true;
    } catch (const NotDoneYet& e) {
        note = e.what();
    }
    return false;
}

} // namespace

Table studyFarSpheres(const StudyOptions& options) {
    Table table{"far_spheres",
                "Rays aimed uniformly over a disc of twice the radius around the sphere, camera at the origin; "
                "errors against a long double evaluation on the same float inputs",
                {"radius", "distance / radius", "method", "hit/miss wrong %", "wrong rays within (radii of the silhouette)",
                 "median t rel. error",
                 "max t rel. error", "median normal error (rad)", "max normal error (rad)", "max cosine shading error"},
                {}};
    for (double radius : {1e-3, 1., 1e3})
        for (double ratio : {1e1, 1e2, 1e3, 1e4, 1e5}) {
            const RaySet set = aimedRays(glm::dvec3(0.), ratio * radius, radius, 2., options.rays);
            for (const NamedMethod& m : methods()) {
                Errors e;
                std::string note;
                if (!runLab([&] { e = measure(set, m.method); }, note)) {
                    table.add({sci(radius, 0), sci(ratio, 0), m.name, note, "", "", "", "", "", ""});
                    continue;
                }
                table.add({sci(radius, 0), sci(ratio, 0), m.name, fixed(100. * double(e.misclassified) / double(e.rays), 3),
                           e.misclassified ? sci(e.wrongBand) : "-", sci(median(e.t)), sci(maximum(e.t)), sci(median(e.normal)), sci(maximum(e.normal)), sci(maximum(e.shading))});
            }
        }
    return table;
}

Table studyIntersectionTimes(const StudyOptions& options) {
    Table table{"intersection_times",
                "Nanoseconds per intersection (hit test and nearest t, no normal), one thread, median of " +
                    std::to_string(options.repeats) + " runs over " + std::to_string(options.rays) +
                    " rays near a radius-1 sphere 1000 away",
                {"method", "ns per intersection", "min ns", "max ns"},
                {}};
    const RaySet set = aimedRays(glm::dvec3(0.), 1e3, 1., 2., options.rays);
    auto timeIt = [&](const char* name, const std::function<double()>& pass) {
        std::vector<double> ns;
        std::string note;
        volatile double sink = 0.;
        if (!runLab([&] { sink = sink + pass(); }, note)) { // one warm-up run, and the stub check
            table.add({name, note, "", ""});
            return;
        }
        for (int r = 0; r < options.repeats; ++r) {
            const auto start = std::chrono::steady_clock::now();
            sink = sink + pass();
            const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            ns.push_back(seconds * 1e9 / double(set.directions.size()));
        }
        table.add({name, fixed(median(ns), 2), fixed(*std::min_element(ns.begin(), ns.end()), 2), fixed(maximum(ns), 2)});
    };
    // The sum of the t's keeps the compiler from dropping the work.
    auto templated = [&](auto tag, bool stable) {
        using T = decltype(tag);
        return [&set, stable] {
            const V3<T> o = V3<T>::from(set.origin), c = V3<T>::from(set.centre);
            double sum = 0.;
            for (const glm::vec3& dir : set.directions) {
                const V3<T> d = V3<T>::from(dir);
                const SphereHit<T> h = stable ? stableIntersect(o, d, c, T(set.radius), T(0), T(kInf))
                                              : textbookIntersect(o, d, c, T(set.radius), T(0), T(kInf));
                sum += h.hit ? double(h.t) : 0.;
            }
            return sum;
        };
    };
    timeIt("textbook float", templated(float{}, false));
    timeIt("stable float", templated(float{}, true));
    timeIt("textbook double", templated(double{}, false));
    timeIt("stable double", templated(double{}, true));
    timeIt("stable long double (the reference)", templated(LD{}, true));
    timeIt("lab code: SphereGeometry::intersect", [&set] {
        const SphereGeometry sphere(set.centre, set.radius, Color(1.f));
        double sum = 0.;
        for (const glm::vec3& dir : set.directions) {
            HitRecord hit;
            if (sphere.intersect(Ray{set.origin, dir}, 0.f, kInf, hit)) sum += hit.t;
        }
        return sum;
    });
    return table;
}

namespace {

// One row of the large-coordinates table: the lab code on `set` (the world's rays, in `spaceName`)
// against the exact answer on the world's.
void addLargeCoordinatesRow(Table& table, double offset, const char* spaceName, const RaySet& world, const RaySet& set) {
    std::int64_t wrong = 0;
    std::vector<double> normalErr, shadeErr;
    std::string note;
    const bool done = runLab([&] {
        for (const glm::vec3& d : world.directions) {
            const Answer truth = formula<LD, true>(world, d); // always the world inputs
            const Answer got = labCode(set, d);
            if (got.hit != truth.hit) ++wrong;
            if (!got.hit || !truth.hit) continue;
            normalErr.push_back(double(angleBetween(got.normal, truth.normal)));
            const V3<LD> dd = V3<LD>::from(d);
            shadeErr.push_back(double(std::abs(std::max(-dot(dd, got.normal), LD(0)) - std::max(-dot(dd, truth.normal), LD(0)))));
        }
    }, note);
    if (!done) {
        table.add({sci(offset, 0), spaceName, note, "", "", ""});
        return;
    }
    table.add({offset == 0. ? "0" : sci(offset, 0), spaceName, fixed(100. * double(wrong) / double(world.directions.size()), 3),
               sci(maximum(normalErr)), sci(maximum(shadeErr)), sci(median(normalErr))});
}

} // namespace

Table studyLargeCoordinates(const StudyOptions& options) {
    Table table{"large_coordinates",
                "A radius-1 sphere 3 away from a camera placed `offset` from the world origin; rays over 99% of "
                "its disc; lab code in world coordinates (hit.position = o + t d) and in raylab's render space "
                "(RenderSpace: the world moved by a multiple of 1024 near the camera, see render_space.h)",
                {"offset", "space", "hit/miss wrong %", "max normal error (rad)", "max shading error", "median normal error (rad)"},
                {}};
    const int rays = std::max(1, options.rays / 4);
    for (double offset : {0., 1e3, 1e4, 1e5, 1e6, 1e7}) {
        const RaySet world = aimedRays(glm::dvec3(0.6, 0., 0.8) * offset, 3., 1., 0.99, rays);
        RaySet relative = world; // the same float scene in raylab's render space
        const RenderSpace space(world.origin);
        relative.origin = space.toRender(world.origin);
        relative.centre = space.toRender(world.centre);
        addLargeCoordinatesRow(table, offset, "world", world, world);
        addLargeCoordinatesRow(table, offset, "render space", world, relative);
    }
    return table;
}

} // namespace raylab::study
