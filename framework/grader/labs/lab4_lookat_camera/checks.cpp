// Lab 4's function checks: the lookAt basis of the handout's four cameras, of cameras whose `up`
// is not perpendicular to the view direction, and of cameras drawn at grading time; the viewport
// of a camera rebuilt after construction; and the cameras that cannot be built.
#include "answers.h"
#include "grader/judge/checks/checks.h"
#include "probes.h"

#include "src/messages.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <functional>
#include <utility>

namespace raylab::grader {

namespace {

using probes::BuiltCamera;

// The probe's camera, with what the messages call it and what the checks expect of it.
struct LookAt : probes::LookAtCamera {
    std::string name;

    LookAt(std::string name, const glm::dvec3& position, const glm::dvec3& target, const glm::dvec3& up,
           int width = 600, int height = 400, double fovy = 60.)
        : probes::LookAtCamera{width, height, position, target, up, fovy}, name(std::move(name)) {}

    glm::dvec3 w() const { return lab4::lookAt(position, target, up).w; }
    glm::dvec3 u() const { return lab4::lookAt(position, target, up).u; }
    glm::dvec3 v() const { return lab4::lookAt(position, target, up).v; }
    double viewportHeight() const { return lab4::viewport(fovy, width, height).height; }
    double viewportWidth() const { return lab4::viewport(fovy, width, height).width; }
    glm::dvec3 topLeft() const { return lab4::topLeft(lab4::lookAt(position, target, up), lab4::viewport(fovy, width, height)); }
    protocol::Call call() const { return probes::lookAt(*this); }
};

// The cameras of scenes/lab4_{a,b,c,d}.toml (named when the checks are made: in the reader's language).
std::vector<LookAt> handoutCameras() {
    auto name = [](const char* letter) { return tr("what.lab4.handout_camera", {{"letter", letter}}); };
    return {{name("a"), {0., 0., -2.}, {0., 0., 79.}, {0., 1., 0.}},
            {name("b"), {1., 0., 0.}, {1., 0., 1.}, {0., 1., 0.}},
            {name("c"), {0., 1., 0.}, {0., 1., 1.}, {0., 1., 0.}},
            {name("d"), {4., -1., 0.}, {-1., -1., 2.}, {0., 1., 0.}}};
}

// A camera whose up leans towards the view direction: v = up or an unnormalized u shows there.
LookAt drawnCamera(CaseRandom& random) {
    LookAt c{"", CaseRandom::asFloat(random.vec3(-5., 5.)), {}, {}};
    c.target = CaseRandom::asFloat(c.position + random.unitVector() * random.uniform(1., 10.));
    const glm::dvec3 view = glm::normalize(c.target - c.position);
    for (;;) {
        c.up = CaseRandom::asFloat(random.unitVector() * random.uniform(0.5, 3.));
        const double cosine = std::abs(glm::dot(glm::normalize(c.up), view));
        if (cosine > 0.2 && cosine < 0.9) break; // oblique, and far from parallel
    }
    c.name = tr("what.lab4.drawn_camera", {{"position", show(c.position)}, {"target", show(c.target)}, {"up", show(c.up)}});
    c.height = random.integer(100, 800);
    c.width = int(c.height * random.uniform(0.5, 2.5));
    c.fovy = CaseRandom::asFloat(random.uniform(30., 100.));
    return c;
}

// A lookAt check, one call a camera: `expect` judges what each camera was built as.
FunctionCheck lookAtCheck(std::string name, std::vector<LookAt> cameras,
                          std::function<void(const LookAt& camera, const BuiltCamera& built, Judge& judge)> expect) {
    std::vector<protocol::Call> calls;
    for (const LookAt& c : cameras) calls.push_back(c.call());
    return {std::move(name), std::move(calls), [cameras, expect](const auto& out, Judge& judge) {
                for (std::size_t k = 0; k < cameras.size(); ++k)
                    expect(cameras[k], probes::lookAt.answer(out[k]), judge);
            }};
}

void addChecks(LabChecks& checks, CaseRandom& random) {
    std::vector<LookAt> cameras = handoutCameras();
    const glm::dvec3 obliqueUp{0.3, 1., 0.4};
    cameras.push_back({tr("what.lab4.oblique_camera", {{"up", show(obliqueUp)}}), {4., -1., 0.}, {-1., -1., 2.}, obliqueUp});
    cameras.push_back(drawnCamera(random));
    cameras.push_back(drawnCamera(random));
    checks.add(lookAtCheck("four_cameras", cameras,
                          [](const LookAt& c, const BuiltCamera& b, Judge& judge) {
                              auto what = [&c](const char* part) {
                                  return tr("what.lab4.part", {{"camera", c.name}, {"part", part}});
                              };
                              // A part made rightly from a wrong part before it is sent to that part; a
                              // mistake is named only when the part is what that mistake makes of it.
                              const glm::dvec3 w = c.w(), u = c.u(), v = c.v();
                              const bool wRight = judge.expectNear(what("w"), b.w, w, 1e-5, tr("hint.lab4.w"),
                                                                   {{-w, tr("hint.lab4.w_reversed")}});
                              const bool uFromW = withinEach(b.u, glm::normalize(glm::cross(c.up, b.w)), 1e-5);
                              bool uRight = true;
                              if (!wRight && uFromW)
                                  uRight = judge.expectNear(what("u"), b.u, u, 1e-5, tr("hint.lab4.from_w"));
                              else
                                  uRight = judge.expectNear(what("u"), b.u, u, 1e-5, tr("hint.lab4.u"),
                                                            {{-u, tr("hint.lab4.u_order")},
                                                             {glm::cross(c.up, w), tr("hint.lab4.u_unit")},
                                                             {v, tr("hint.lab4.u_v_exchanged")}});
                              const bool vFromFrame = withinEach(b.v, glm::cross(b.w, b.u), 1e-5);
                              if (vFromFrame && !(wRight && uRight))
                                  judge.expectNear(what("v"), b.v, v, 1e-5, tr(wRight ? "hint.lab4.from_u" : "hint.lab4.from_w"));
                              else
                                  judge.expectNear(what("v"), b.v, v, 1e-5, tr("hint.lab4.v"),
                                                   {{-v, tr("hint.lab4.v_order")},
                                                    {u, tr("hint.lab4.u_v_exchanged")},
                                                    {c.up, tr("hint.lab4.v_is_up")},
                                                    {glm::normalize(c.up), tr("hint.lab4.v_is_up")}});
                              judge.expectNear(what("position"), b.position, c.position, 1e-6,
                                               tr("hint.lab4.position"));
                          }));

    const std::vector<LookAt> moved{handoutCameras()[3], drawnCamera(random)};
    checks.add(lookAtCheck(
        "viewport_follows", moved, [](const LookAt& c, const BuiltCamera& b, Judge& judge) {
            // A screen placed rightly in a wrong frame: updateViewport was called, the frame is at fault.
            const glm::dvec3 ownTopLeft =
         b.position - b.w + b.v * (b.viewportHeight / 2.) - b.u * (b.viewportWidth / 2.);
            const bool frameRight = withinEach(b.u, c.u(), 1e-5) && withinEach(b.v, c.v(), 1e-5) && withinEach(b.w, c.w(), 1e-5);
            auto what = [&c](const std::string& part) { return tr("what.lab4.part", {{"camera", c.name}, {"part", part}}); };
            judge.expectNear(what(tr("what.lab4.viewport_height")), b.viewportHeight, c.viewportHeight(), 1e-5,
                             tr("hint.lab4.viewport_size"));
            judge.expectNear(what(tr("what.lab4.viewport_width")), b.viewportWidth, c.viewportWidth(), 1e-5,
                             tr("hint.lab4.viewport_size"));
            if (!frameRight && withinEach(b.topLeft, ownTopLeft, 1e-4)) {
                judge.expectNear(what(tr("what.lab4.top_left")), b.topLeft, c.topLeft(), 1e-4, tr("hint.lab4.viewport_frame"));
                return;
            }
            // The default camera's screen (at the origin, u = (-1, 0, 0), v = (0, 1, 0), w = (0, 0, -1)), which
            // the delegated constructor places; and the right frame's screen placed before the position was set.
            const glm::dvec3 defaultTopLeft{c.viewportWidth() / 2., c.viewportHeight() / 2., 1.};
            judge.expectNear(what(tr("what.lab4.top_left")), b.topLeft, c.topLeft(), 1e-4, tr("hint.lab4.top_left"),
                             {{defaultTopLeft, tr("hint.lab4.viewport")},
                              {c.topLeft() - c.position, tr("hint.lab4.viewport_position")}});
        }));

    // The default camera is what the delegated constructor already built: the same camera turned
    // round (looking along -z) shows that lookAt built it, and the same handedness.
    const LookAt origin{"", {0., 0., 0.}, {0., 0., 1.}, {0., 1., 0.}};
    const LookAt turned{"", {0., 0., 0.}, {0., 0., -1.}, {0., 1., 0.}};
    checks.add(
        {"default_as_lookat", {origin.call(), turned.call()}, [](const auto& out, Judge& judge) {
      const BuiltCamera b = probes::lookAt.answer(out[0]), t = probes::lookAt.answer(out[1]);
      judge.expectNear("u", b.u, {-1., 0., 0.}, 1e-6, tr("hint.lab4.default_u"));
      judge.expectNear("v", b.v, {0., 1., 0.}, 1e-6, tr("hint.lab4.default_v"));
      const std::string turnedPart = tr("what.lab4.turned_camera");
      judge.expectNear(tr("what.lab4.part", {{"camera", turnedPart}, {"part", "u"}}), t.u, {1., 0., 0.}, 1e-6,
                       tr("hint.lab4.turned_u"));
      judge.expectNear(tr("what.lab4.part", {{"camera", turnedPart}, {"part", "v"}}), t.v, {0., 1., 0.}, 1e-6,
                       tr("hint.lab4.default_v"));
         }});

    // A constructor that refuses everything earns nothing: a valid camera must be built first, and
    // built by lookAt (not the default camera, which the delegated constructor already gives).
    const LookAt valid{"", {1., 2., 3.}, {3., 1., 5.}, {0., 1., 0.}, 200, 100};
    const glm::dvec3 p = CaseRandom::asFloat(random.vec3(-5., 5.));
    // Along an axis, so that the view and up are exactly parallel in float too.
    const glm::dvec3 along{0., double(random.integer(1, 9)) * (random.integer(0, 1) ? 1. : -1.), 0.};
    checks.add(
        {"degenerate_refused",
         {valid.call(), probes::lookAtRefused({0., 0., 0.}, {0., 2., 0.}, {0., 1., 0.}),
          probes::lookAtRefused({1., 2., 3.}, {1., 2., 3.}, {0., 1., 0.}), probes::lookAtRefused(p, p, {0., 1., 0.}),
          probes::lookAtRefused(p, p + along, {0., 2., 0.})},
         [p](const auto& out, Judge& judge) {
      const BuiltCamera built = probes::lookAt.answer(out[0]);
      judge.expectNear(tr("what.lab4.valid_w"), built.w, {-2. / 3., 1. / 3., -2. / 3.}, 1e-6, tr("hint.lab4.valid_w"));
      judge.expectNear(tr("what.lab4.valid_position"), built.position, {1., 2., 3.}, 1e-6, tr("hint.lab4.position"));
      const std::string names[] = {tr("what.lab4.up_parallel"), tr("what.lab4.position_is_target"),
                                   tr("what.lab4.position_is_target_at", {{"position", show(p)}}),
                                   tr("what.lab4.up_parallel_from", {{"position", show(p)}})};
      for (std::size_t k = 1; k < out.size(); ++k)
          judge.expectTrue(names[k - 1], probes::lookAtRefused.answer(out[k]), tr("what.lab4.refused"),
                           tr("what.lab4.built"), tr("hint.lab4.refuse"));
         }});
}

} // namespace

RAYLAB_REGISTER_CHECKS(addChecks);

} // namespace raylab::grader
