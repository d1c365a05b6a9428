// Lab 2's function checks: the viewport and the primary rays of known cameras and of cameras
// drawn at grading time. Every camera is built without lookAt (lab 4): lab 2 is graded on its own.
#include "grader/checks/checks.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>

namespace raylab::grader {

namespace {

using protocol::Probe;

struct Camera {
    int width, height;
    double fovy;
    glm::dvec3 position{0.};
    double viewportHeight() const { return 2. * std::tan(fovy / 2. * std::numbers::pi / 180.); }
    double viewportWidth() const { return viewportHeight() * width / height; }
    // The default frame: u = (-1, 0, 0), v = (0, 1, 0), looking along +z (docs/conventions.md).
    glm::dvec3 topLeft() const { return position + glm::dvec3(viewportWidth() / 2., viewportHeight() / 2., 1.); }
    glm::dvec3 direction(double sx, double sy) const { return direction(sx, sy, viewportHeight(), viewportWidth()); }
    // Through a viewport of this height and width in front of the camera (the student's own, say).
    static glm::dvec3 direction(double sx, double sy, double height, double width) {
        return glm::normalize(glm::dvec3(width / 2., height / 2., 1.) + sx * width * glm::dvec3(-1., 0., 0.) -
                              sy * height * glm::dvec3(0., 1., 0.));
    }
    protocol::Call viewport() const { return {Probe::Viewport, {double(width), double(height), fovy}}; }
    protocol::Call ray(double sx, double sy) const {
        return {Probe::GenerateRay, {double(width), double(height), fovy, position.x, position.y, position.z, sx, sy}};
    }
    std::string name() const { return std::to_string(width) + " x " + std::to_string(height) + ", fovy " + show(fovy); }
};

// Sizes and angles where a float viewport keeps the checks' 1e-5 (a viewport 10 units wide would not).
Camera drawnCamera(CaseRandom& random) {
    const int height = random.integer(100, 800);
    return {int(height * random.uniform(0.5, 2.5)), height, CaseRandom::asFloat(random.uniform(20., 120.))};
}

void expectViewport(Judge& judge, const Camera& c, const std::vector<double>& out, bool named) {
    Outputs o(out);
    const std::string suffix = named ? " (" + c.name() + ")" : "";
    const double height = o.number(), width = o.number();
    judge.expectNear("viewport height, fovy " + show(c.fovy) + suffix, height, c.viewportHeight(), 1e-5,
                     "height = 2 tan(fovy / 2) * focal: fovy is the full angle, in degrees (glm::radians converts)");
    judge.expectNear("viewport width, " + std::to_string(c.width) + " x " + std::to_string(c.height) + suffix, width,
                     c.viewportWidth(), 1e-5,
                     "width = height * aspect, with aspect = W / H = " + show(double(c.width) / c.height));
    judge.expectNear("top-left corner" + suffix, o.vec3(), c.topLeft(), 1e-5,
                     "topLeft = position - w * focal + v * height / 2 - u * width / 2 (u = (-1, 0, 0) here)");
}

struct Point {
    double sx, sy;
    std::string name;
};

// The viewport the student's updateViewport gave a camera's size and fovy.
struct SeenViewport {
    double height, width;
    bool right; // as updateViewport's checks want it
    SeenViewport(const Camera& c, const std::vector<double>& out) {
        Outputs o(out);
        height = o.number();
        width = o.number();
        right = std::abs(height - c.viewportHeight()) <= 1e-5 && std::abs(width - c.viewportWidth()) <= 1e-5;
    }
};

// generateRay is judged on its own code: when the student's viewport is wrong (updateViewport's
// checks fail and say why), the rays are expected through that viewport, and a failure's hint
// says generateRay inherits the viewport's mistake rather than repeat its formula.
constexpr const char* kDirectionHint =
    "direction = normalize(topLeft + sx * width * u - sy * height * v - position): sx goes right along u, sy goes "
    "down against v";

void expectRays(Judge& judge, const Camera& c, const SeenViewport& viewport, const std::vector<Point>& points,
                const std::vector<std::vector<double>>& out, std::size_t first, const std::string& hint = kDirectionHint) {
    const std::string inherited = "your viewport is wrong (height " + show(viewport.height) + ", width " +
                                  show(viewport.width) + "; see updateViewport's checks) and generateRay inherits it: "
                                  "fix updateViewport first. Through your viewport, the direction is "
                                  "normalize(topLeft + sx * width * u - sy * height * v - position)";
    for (std::size_t k = 0; k < points.size(); ++k) {
        Outputs o(out[first + k]);
        const Point& p = points[k];
        judge.expectNear("ray origin at the " + p.name, o.vec3(), c.position, 1e-6,
                         "a primary ray starts at the camera position");
        if (viewport.right)
            judge.expectNear("ray direction at the " + p.name, o.vec3(), c.direction(p.sx, p.sy), 1e-5, hint);
        else
            judge.expectNear("ray direction at the " + p.name + " through your viewport", o.vec3(),
                             Camera::direction(p.sx, p.sy, viewport.height, viewport.width), 1e-5, inherited);
    }
}

} // namespace

void addLab2Checks(std::vector<FunctionCheck>& checks, CaseRandom& random) {
    const Camera handout{600, 400, 60.};
    const Camera drawn = drawnCamera(random);
    checks.push_back({2,
                      "updateViewport: the viewport of the default camera",
                      {handout.viewport(), drawn.viewport()},
                      [handout, drawn](const auto& out, Judge& judge) {
                          expectViewport(judge, handout, out[0], false);
                          expectViewport(judge, drawn, out[1], true);
                      }});

    const Camera square{100, 100, 90.}, wide{100, 100, CaseRandom::asFloat(random.uniform(20., 120.))};
    checks.push_back(
        {2,
         "updateViewport: fovy is in degrees and halved",
         {square.viewport(), wide.viewport()},
         [square, wide](const auto& out, Judge& judge) {
             const char* hint = "2 tan(fovy / 2), fovy in degrees: convert degrees to radians and take half the angle";
             for (const auto& [c, o] : {std::pair{square, out[0]}, std::pair{wide, out[1]}})
                 judge.expectNear("viewport height, fovy " + show(c.fovy), o[0], c.viewportHeight(), 1e-5, hint);
         }});

    std::vector<Point> corners{{0.5, 0.5, "centre (0.5, 0.5)"},
                               {0., 0., "top-left corner (0, 0)"},
                               {1., 0., "top-right corner (1, 0)"},
                               {0., 1., "bottom-left corner (0, 1)"},
                               {1., 1., "bottom-right corner (1, 1)"}};
    const std::size_t fixedCorners = corners.size();
    const Camera other = drawnCamera(random);
    std::vector<Point> drawnPoints;
    for (int k = 0; k < 3; ++k) {
        const double sx = CaseRandom::asFloat(random.uniform(0., 1.)), sy = CaseRandom::asFloat(random.uniform(0., 1.));
        drawnPoints.push_back({sx, sy, "point (" + show(sx) + ", " + show(sy) + ") of a " + other.name() + " camera"});
    }
    std::vector<protocol::Call> calls;
    for (const Point& p : corners)
        calls.push_back(handout.ray(p.sx, p.sy));
    for (const Point& p : drawnPoints)
        calls.push_back(other.ray(p.sx, p.sy));
    calls.push_back(handout.viewport());
    calls.push_back(other.viewport());
    checks.push_back({2, "generateRay: the centre and the four corners of the default camera", calls,
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
    checks.push_back(
        {2, "generateRay: directions are unit vectors", calls, [screen](const auto& out, Judge& judge) {
             for (std::size_t k = 0; k < screen.size(); ++k) {
                 Outputs o(out[k]);
                 o.vec3();
                 if (!judge.expectNear(
                         "|direction| at (" + show(screen[k].first) + ", " + show(screen[k].second) + ")",
                         glm::length(o.vec3()), 1., 1e-5,
                         "normalize the direction (glm::normalize): shading and t as a distance rely on it"))
                     return;
             }
         }});

    const Camera away{300, 200, 60., {2., 3., -4.}};
    Camera drawnAway = drawnCamera(random);
    drawnAway.position = CaseRandom::asFloat(random.vec3(-5., 5.));
    const double sx = CaseRandom::asFloat(random.uniform(0., 1.)), sy = CaseRandom::asFloat(random.uniform(0., 1.));
    checks.push_back({2,
                      "generateRay: a camera away from the origin starts its rays at its position",
                      {away.ray(0., 0.), drawnAway.ray(sx, sy), away.viewport(), drawnAway.viewport()},
                      [away, drawnAway, sx, sy](const auto& out, Judge& judge) {
                          for (const auto& [c, o, viewport, x, y] :
                               {std::tuple{away, out[0], out[2], 0., 0.}, std::tuple{drawnAway, out[1], out[3], sx, sy}}) {
                              const std::string at = "camera at " + show(c.position);
                              expectRays(judge, c, SeenViewport(c, viewport),
                                         {{x, y, "point (" + show(x) + ", " + show(y) + "), " + at}}, {o}, 0,
                                         "topLeft includes the position (topLeft = position - w * focal + ...) and "
                                         "the direction subtracts it");
                          }
                      }});
}

} // namespace raylab::grader
