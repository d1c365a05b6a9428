// Lab 4's function checks: the lookAt basis of the handout's four cameras, of cameras whose `up`
// is not perpendicular to the view direction, and of cameras drawn at grading time; the viewport
// of a camera rebuilt after construction; and the cameras that cannot be built.
#include "grader/checks/checks.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>

namespace raylab::grader {

namespace {

using protocol::Probe;

struct LookAt {
    std::string name;
    glm::dvec3 position, target, up;
    int width = 600, height = 400;
    double fovy = 60.;

    glm::dvec3 w() const { return glm::normalize(position - target); }
    glm::dvec3 u() const { return glm::normalize(glm::cross(up, w())); }
    glm::dvec3 v() const { return glm::cross(w(), u()); }
    double viewportHeight() const { return 2. * std::tan(fovy / 2. * std::numbers::pi / 180.); }
    double viewportWidth() const { return viewportHeight() * width / height; }
    glm::dvec3 topLeft() const { return position - w() + v() * (viewportHeight() / 2.) - u() * (viewportWidth() / 2.); }
    protocol::Call call() const {
        std::vector<double> in{double(width), double(height)};
        for (const glm::dvec3& p : {position, target, up})
            appendInputs(in, p);
        in.push_back(fovy);
        return {Probe::LookAt, in};
    }
};

// What the LookAt probe returns.
struct Built {
    glm::dvec3 u, v, w, position;
    double viewportHeight, viewportWidth;
    glm::dvec3 topLeft;
    explicit Built(const std::vector<double>& out) {
        Outputs o(out);
        u = o.vec3();
        v = o.vec3();
        w = o.vec3();
        position = o.vec3();
        viewportHeight = o.number();
        viewportWidth = o.number();
        topLeft = o.vec3();
    }
};

// The cameras of scenes/figures/lab4_{a,b,c,d}.toml.
const LookAt kHandoutCameras[] = {
    {"camera (a)", {0., 0., -2.}, {0., 0., 79.}, {0., 1., 0.}},
    {"camera (b)", {1., 0., 0.}, {1., 0., 1.}, {0., 1., 0.}},
    {"camera (c)", {0., 1., 0.}, {0., 1., 1.}, {0., 1., 0.}},
    {"camera (d)", {4., -1., 0.}, {-1., -1., 2.}, {0., 1., 0.}},
};

// A camera whose up leans towards the view direction: v = up or an unnormalized u shows there.
LookAt drawnCamera(CaseRandom& random, const std::string& name) {
    LookAt c{name, CaseRandom::asFloat(random.vec3(-5., 5.)), {}, {}};
    c.target = CaseRandom::asFloat(c.position + random.unitVector() * random.uniform(1., 10.));
    const glm::dvec3 view = glm::normalize(c.target - c.position);
    for (;;) {
        c.up = CaseRandom::asFloat(random.unitVector() * random.uniform(0.5, 3.));
        const double cosine = std::abs(glm::dot(glm::normalize(c.up), view));
        if (cosine > 0.2 && cosine < 0.9) break; // oblique, and far from parallel
    }
    c.name += " at " + show(c.position) + " looking at " + show(c.target) + ", up " + show(c.up);
    c.height = random.integer(100, 800);
    c.width = int(c.height * random.uniform(0.5, 2.5));
    c.fovy = CaseRandom::asFloat(random.uniform(30., 100.));
    return c;
}

protocol::Call refusedCall(const glm::dvec3& position, const glm::dvec3& target, const glm::dvec3& up) {
    std::vector<double> in;
    for (const glm::dvec3& p : {position, target, up})
        appendInputs(in, p);
    return {Probe::LookAtRefused, in};
}

} // namespace

void addLab4Checks(std::vector<FunctionCheck>& checks, CaseRandom& random) {
    std::vector<LookAt> cameras(std::begin(kHandoutCameras), std::end(kHandoutCameras));
    cameras.push_back({"camera (d) with up (0.3, 1, 0.4), not perpendicular to the view",
                       {4., -1., 0.},
                       {-1., -1., 2.},
                       {0.3, 1., 0.4}});
    cameras.push_back(drawnCamera(random, "a camera"));
    cameras.push_back(drawnCamera(random, "a camera"));
    std::vector<protocol::Call> calls;
    for (const LookAt& c : cameras)
        calls.push_back(c.call());
    checks.push_back(
        {4, "lookAt: the basis of the handout's four cameras", calls, [cameras](const auto& out, Judge& judge) {
             for (std::size_t k = 0; k < cameras.size(); ++k) {
                 const LookAt& c = cameras[k];
                 const Built b(out[k]);
                 judge.expectNear(c.name + ": w", b.w, c.w(), 1e-5,
                                  "w = normalize(position - target): the camera looks along -w");
                 judge.expectNear(c.name + ": u", b.u, c.u(), 1e-5,
                                  "u = normalize(cross(up, w)) in this order: cross(w, up) mirrors the image, and "
                                  "cross(up, w) is unit only when up is perpendicular to w");
                 judge.expectNear(c.name + ": v", b.v, c.v(), 1e-5,
                                  "v = cross(w, u), up in the image: `up` only gives the side, it need not be "
                                  "perpendicular to w");
                 judge.expectNear(c.name + ": position", b.position, c.position, 1e-6,
                                  "store the position in m_position");
             }
         }});

    const std::vector<LookAt> moved{kHandoutCameras[3], drawnCamera(random, "a camera")};
    calls.clear();
    for (const LookAt& c : moved)
        calls.push_back(c.call());
    checks.push_back(
        {4, "lookAt: the viewport follows the new frame", calls, [moved](const auto& out, Judge& judge) {
             for (std::size_t k = 0; k < moved.size(); ++k) {
                 const LookAt& c = moved[k];
                 const Built b(out[k]);
                 const char* hint = "call updateViewport() after setting the frame, so the screen is in front of "
                                    "the new camera (a camera built, then rebuilt elsewhere, must move its screen too)";
                 judge.expectNear(c.name + ": viewport height", b.viewportHeight, c.viewportHeight(), 1e-5, hint);
                 judge.expectNear(c.name + ": viewport width", b.viewportWidth, c.viewportWidth(), 1e-5, hint);
                 judge.expectNear(c.name + ": top-left corner", b.topLeft, c.topLeft(), 1e-4,
                                  std::string(hint) + "; set m_position before updateViewport()");
             }
         }});

    const LookAt origin{
        "the default camera as lookAt((0,0,0), (0,0,1), (0,1,0))", {0., 0., 0.}, {0., 0., 1.}, {0., 1., 0.}};
    checks.push_back(
        {4, "lookAt: the default camera as a lookAt camera", {origin.call()}, [](const auto& out, Judge& judge) {
             const Built b(out[0]);
             judge.expectNear("u", b.u, {-1., 0., 0.}, 1e-6,
                              "lookAt((0,0,0), (0,0,1), (0,1,0)) is the default camera, whose u is (-1, 0, 0)");
             judge.expectNear("v", b.v, {0., 1., 0.}, 1e-6, "v = cross(w, u)");
         }});

    // A constructor that refuses everything earns nothing: a valid camera must be built first.
    const LookAt valid{"a valid camera", {0., 0., 0.}, {0., 0., 1.}, {0., 1., 0.}, 200, 100};
    const glm::dvec3 p = CaseRandom::asFloat(random.vec3(-5., 5.));
    // Along an axis, so that the view and up are exactly parallel in float too.
    const glm::dvec3 along{0., double(random.integer(1, 9)) * (random.integer(0, 1) ? 1. : -1.), 0.};
    checks.push_back(
        {4,
         "lookAt: a degenerate camera is refused with an error",
         {valid.call(), refusedCall({0., 0., 0.}, {0., 2., 0.}, {0., 1., 0.}),
          refusedCall({1., 2., 3.}, {1., 2., 3.}, {0., 1., 0.}), refusedCall(p, p, {0., 1., 0.}),
          refusedCall(p, p + along, {0., 2., 0.})},
         [p](const auto& out, Judge& judge) {
             judge.expectNear("a valid camera's w", Built(out[0]).w, {0., 0., -1.}, 1e-6,
                              "w = normalize(position - target)");
             const std::string names[] = {"up parallel to the view direction", "position equal to the target",
                                          "position equal to the target, both " + show(p),
                                          "up parallel to the view direction, from " + show(p)};
             for (std::size_t k = 1; k < out.size(); ++k)
                 judge.expectTrue(
                     names[k - 1], out[k][0] == 1., "std::invalid_argument naming the parameter", "a camera was built",
                     "keep the given checkLookAtParameters(position, target, up) call at the top of the constructor");
         }});
}

} // namespace raylab::grader
