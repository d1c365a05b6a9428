// Lab 2's function checks: the viewport and the primary rays of known cameras and of cameras
// drawn at grading time. Every camera is built without lookAt (lab 4): lab 2 is graded on its own.
#include "answers.h"
#include "grader/judge/checks/checks.h"
#include "probes.h"

#include "src/messages.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>

namespace raylab::grader {

namespace {

// The probe's camera, with what the checks expect of it and the calls that ask the student's code.
struct Camera : probes::DefaultFrameCamera {
    double viewportHeight() const { return lab2::viewport(fovy, width, height).height; }
    double viewportWidth() const { return lab2::viewport(fovy, width, height).width; }
    glm::dvec3 topLeft() const { return lab2::topLeft(lab2::defaultFrame(position), lab2::viewport(fovy, width, height)); }
    glm::dvec3 direction(double sx, double sy) const { return direction(sx, sy, viewportHeight(), viewportWidth()); }
    // Through a viewport of this height and width in front of the camera (the student's own, say).
    static glm::dvec3 direction(double sx, double sy, double height, double width) {
        return lab2::direction(lab2::defaultFrame(glm::dvec3(0.)), {height, width}, sx, sy);
    }
    protocol::Call viewport() const { return probes::viewport(width, height, fovy); }
    protocol::Call ray(double sx, double sy) const { return probes::generateRay(*this, sx, sy); }
    std::string name() const {
        return tr("what.lab2.camera", {{"width", std::to_string(width)}, {"height", std::to_string(height)}, {"fovy", show(fovy)}});
    }
};

// Sizes and angles where a float viewport keeps the checks' 1e-5 (a viewport 10 units wide would not).
Camera drawnCamera(CaseRandom& random) {
    const int height = random.integer(100, 800);
    return {int(height * random.uniform(0.5, 2.5)), height, CaseRandom::asFloat(random.uniform(20., 120.))};
}

// The classic mistakes of the viewport's height, each with the height it gives for `c`.
std::vector<Suspect<double>> heightSuspects(const Camera& c) {
    return {{2. * std::tan(c.fovy * std::numbers::pi / 180.), tr("hint.lab2.not_halved")},
            {2. * std::tan(c.fovy / 2.), tr("hint.lab2.degrees_as_radians")}};
}

void expectViewport(Judge& judge, const Camera& c, const std::vector<double>& out, bool named) {
    const std::string suffix = named ? " (" + c.name() + ")" : "";
    const auto [height, width, topLeft] = probes::viewport.answer(out);
    const bool heightRight = judge.expectNear(tr("what.lab2.viewport_height", {{"fovy", show(c.fovy)}}) + suffix, height,
                                              c.viewportHeight(), 1e-5, tr("hint.lab2.viewport_height"), heightSuspects(c));
    const double aspect = double(c.width) / c.height;
    const std::string widthWhat =
        tr("what.lab2.viewport_width", {{"width", std::to_string(c.width)}, {"height", std::to_string(c.height)}}) + suffix;
    // A width made rightly from a wrong height is sent to the height.
    if (!heightRight && std::abs(width - height * aspect) <= 1e-5)
        judge.expectNear(widthWhat, width, c.viewportWidth(), 1e-5, tr("hint.lab2.width_from_height"));
    else
        judge.expectNear(widthWhat, width, c.viewportWidth(), 1e-5, tr("hint.lab2.viewport_width", {{"aspect", show(aspect)}}),
                         {{c.viewportHeight() / aspect, tr("hint.lab2.aspect_inverted")},
                          {height / aspect, tr("hint.lab2.aspect_inverted")}});
    judge.expectNear(tr("what.lab2.top_left") + suffix, topLeft, c.topLeft(), 1e-5, tr("hint.lab2.top_left"));
}

struct Point {
    double sx, sy;
    std::string name;
};

// The viewport the student's updateViewport gave a camera's size and fovy.
struct SeenViewport {
    double height, width;
    bool right; // as updateViewport's checks want it
    // A viewport of no size (updateViewport not written) sends every ray through one point: rays
    // through it say nothing of generateRay's code, so they are then expected through the right one.
    bool sized;
    SeenViewport(const Camera& c, const std::vector<double>& out) {
        const probes::Viewport seen = probes::viewport.answer(out);
        height = seen.height;
        width = seen.width;
        right = std::abs(height - c.viewportHeight()) <= 1e-5 && std::abs(width - c.viewportWidth()) <= 1e-5;
        sized = std::isfinite(height) && std::isfinite(width) && std::abs(height) > 1e-6 && std::abs(width) > 1e-6;
    }
};

// generateRay is judged on its own code: when the student's viewport is wrong (updateViewport's
// checks fail and say why), the rays are expected through that viewport, and a failure's hint
// says generateRay inherits the viewport's mistake rather than repeat its formula.
void expectRays(Judge& judge, const Camera& c, const SeenViewport& viewport, const std::vector<Point>& points,
                const std::vector<std::vector<double>>& out, std::size_t first,
                const std::string& hint = tr("hint.lab2.ray_direction")) {
    const std::string inherited =
        tr("hint.lab2.inherited_viewport", {{"height", show(viewport.height)}, {"width", show(viewport.width)}});
    for (std::size_t k = 0; k < points.size(); ++k) {
        const auto [origin, direction] = probes::generateRay.answer(out[first + k]);
        const Point& p = points[k];
        const std::string what = tr("what.lab2.ray_direction_at", {{"point", p.name}});
        judge.expectNear(tr("what.lab2.ray_origin_at", {{"point", p.name}}), origin, c.position, 1e-6,
                         tr("hint.lab2.ray_origin"));
        // A viewport with no size (zero, not finite) is not inherited: the rays are judged against the right one.
        const bool ownViewport = viewport.right || !viewport.sized;
        const glm::dvec3 expected = ownViewport ? c.direction(p.sx, p.sy)
                                                : Camera::direction(p.sx, p.sy, viewport.height, viewport.width);
        // The right way but not unit length: the normalisation is missing, not sx or sy.
        const double length = glm::length(direction);
        const bool notUnit =
            length > 0. && std::abs(length - 1.) > 1e-5 && glm::length(direction / length - expected) <= 1e-5;
        const std::string unitHint = tr("hint.lab2.not_unit", {{"length", show(length)}});
        if (viewport.right)
            judge.expectNear(what, direction, expected, 1e-5, notUnit ? unitHint : hint);
        else if (!viewport.sized)
            judge.expectNear(what, direction, expected, 1e-5,
                             tr("hint.lab2.no_viewport", {{"height", show(viewport.height)}, {"width", show(viewport.width)}}));
        else
            judge.expectNear(tr("what.lab2.through_viewport", {{"what", what}}), direction, expected, 1e-5,
                             notUnit ? unitHint : inherited);
    }
}

void addChecks(LabChecks& checks, CaseRandom& random) {
    const Camera handout{600, 400, 60.};
    const Camera drawn = drawnCamera(random);
    checks.add({"default_viewport",
               {handout.viewport(), drawn.viewport()},
               [handout, drawn](const auto& out, Judge& judge) {
                   expectViewport(judge, handout, out[0], false);
                   expectViewport(judge, drawn, out[1], true);
               }});

    const Camera square{100, 100, 90.}, wide{100, 100, CaseRandom::asFloat(random.uniform(20., 120.))};
    checks.add(
        {"fovy_degrees",
         {square.viewport(), wide.viewport()},
         [square, wide](const auto& out, Judge& judge) {
      const std::string hint = tr("hint.lab2.fovy_degrees_halved");
      for (const auto& [c, o] : {std::pair{square, out[0]}, std::pair{wide, out[1]}})
          judge.expectNear(tr("what.lab2.viewport_height", {{"fovy", show(c.fovy)}}), probes::viewport.answer(o).height,
                           c.viewportHeight(), 1e-5, hint, heightSuspects(c));
         }});

    std::vector<Point> corners{{0.5, 0.5, tr("what.lab2.centre", {{"sx", show(0.5)}, {"sy", show(0.5)}})},
                               {0., 0., tr("what.lab2.top_left_corner")},
                               {1., 0., tr("what.lab2.top_right_corner")},
                               {0., 1., tr("what.lab2.bottom_left_corner")},
                               {1., 1., tr("what.lab2.bottom_right_corner")}};
    const std::size_t fixedCorners = corners.size();
    const Camera other = drawnCamera(random);
    std::vector<Point> drawnPoints;
    for (int k = 0; k < 3; ++k) {
        const double sx = CaseRandom::asFloat(random.uniform(0., 1.)), sy = CaseRandom::asFloat(random.uniform(0., 1.));
        drawnPoints.push_back({sx, sy, tr("what.lab2.point_of_camera", {{"sx", show(sx)}, {"sy", show(sy)}, {"camera", other.name()}})});
    }
    std::vector<protocol::Call> calls;
    for (const Point& p : corners)
        calls.push_back(handout.ray(p.sx, p.sy));
    for (const Point& p : drawnPoints)
        calls.push_back(other.ray(p.sx, p.sy));
    calls.push_back(handout.viewport());
    calls.push_back(other.viewport());
    checks.add({"centre_and_corners", calls,
               [handout, other, corners, drawnPoints, fixedCorners](const auto& out, Judge& judge) {
                   const std::size_t viewports = fixedCorners + drawnPoints.size();
                   expectRays(judge, handout, SeenViewport(handout, out[viewports]), corners, out, 0);
                   expectRays(judge, other, SeenViewport(other, out[viewports + 1]), drawnPoints, out,
                              fixedCorners);
               }});

    const Camera unit{640, 480, 75.};
    std::vector<std::pair<double, double>> screen;
    for (double sx : {0., 0.3, 1.})
        for (double sy : {0., 0.7, 1.})
            screen.emplace_back(CaseRandom::asFloat(sx), CaseRandom::asFloat(sy));
    for (int k = 0; k < 3; ++k)
        screen.emplace_back(CaseRandom::asFloat(random.uniform(0., 1.)), CaseRandom::asFloat(random.uniform(0., 1.)));
    calls.clear();
    for (const auto& [sx, sy] : screen)
        calls.push_back(unit.ray(sx, sy));
    checks.add(
        {"unit_directions", calls, [screen](const auto& out, Judge& judge) {
      // A direction that ignores (sx, sy), such as Ray{}'s, is a unit vector without normalizing anything.
      const glm::dvec3 first = probes::generateRay.answer(out[0]).direction;
      bool follows = false;
      for (std::size_t k = 1; k < screen.size(); ++k)
          follows = follows || !withinEach(probes::generateRay.answer(out[k]).direction, first, 1e-6);
      if (!judge.expectTrue(tr("what.lab2.directions_follow"), follows, tr("what.lab2.directions_differ"),
                            tr("what.lab2.one_direction", {{"direction", show(first)}}), tr("hint.lab2.one_direction")))
          return;
      for (std::size_t k = 0; k < screen.size(); ++k) {
          if (!judge.expectNear(
                  tr("what.lab2.direction_length", {{"sx", show(screen[k].first)}, {"sy", show(screen[k].second)}}),
                  glm::length(probes::generateRay.answer(out[k]).direction), 1., 1e-5, tr("hint.lab2.normalize")))
              return;
      }
         }});

    const Camera away{300, 200, 60., {2., 3., -4.}};
    Camera drawnAway = drawnCamera(random);
    drawnAway.position = CaseRandom::asFloat(random.vec3(-5., 5.));
    const double sx = CaseRandom::asFloat(random.uniform(0., 1.)), sy = CaseRandom::asFloat(random.uniform(0., 1.));
    // The same rays from cameras at the origin: a direction as wrong there as here is not the
    // position's fault, and the hint says so instead of blaming the position.
    Camera awayAtOrigin = away, drawnAtOrigin = drawnAway;
    awayAtOrigin.position = drawnAtOrigin.position = glm::dvec3(0.);
    checks.add({"moved_camera",
               {away.ray(0., 0.), drawnAway.ray(sx, sy), away.viewport(), drawnAway.viewport(),
                awayAtOrigin.ray(0., 0.), drawnAtOrigin.ray(sx, sy)},
               [away, drawnAway, sx, sy](const auto& out, Judge& judge) {
                   for (const auto& [c, o, viewport, atOrigin, x, y] :
                        {std::tuple{away, out[0], out[2], out[4], 0., 0.},
                         std::tuple{drawnAway, out[1], out[3], out[5], sx, sy}}) {
                       const bool sameAsAtOrigin = withinEach(probes::generateRay.answer(o).direction,
                                                              probes::generateRay.answer(atOrigin).direction, 1e-5);
                       expectRays(judge, c, SeenViewport(c, viewport),
                                  {{x, y, tr("what.lab2.away_point", {{"sx", show(x)}, {"sy", show(y)},
                                                                      {"position", show(c.position)}})}},
                                  {o}, 0, tr(sameAsAtOrigin ? "hint.lab2.away_as_at_origin" : "hint.lab2.away_direction"));
                   }
               }});
}

} // namespace

RAYLAB_REGISTER_CHECKS(addChecks);

} // namespace raylab::grader
