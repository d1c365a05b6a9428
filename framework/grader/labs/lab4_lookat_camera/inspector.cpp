// Lab 4's rows of the pixel inspector (grader/inspector/inspector_steps.h): the lookAt camera's frame
// and its screen's top-left corner, asked of the constructor, and the reference's ray through the
// pixel centre, which the rows of what it meets (lab 3's, lab 6's) follow. The handout's frame:
// w = normalize(position - target), u = normalize(cross(up, w)), v = cross(w, u), the screen at 1.
#include "grader/inspector/inspector_steps.h"
#include "probes.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>

namespace raylab::grader::inspector {

namespace {

void lookAtCamera(PixelContext& pixel, Inspection& inspection) {
    const SceneDescription& d = pixel.scene;
    if (d.samples != 1 || !d.camera.lookAt || pixel.ray) return;
    const double sx = (pixel.x + 0.5) / d.width, sy = (pixel.y + 0.5) / d.height;
    const glm::dvec3 position(d.camera.position), target(d.camera.target), up(d.camera.up);
    const glm::dvec3 w = glm::normalize(position - target), u = glm::normalize(glm::cross(up, w)), v = glm::cross(w, u);
    const double height = 2. * std::tan(double(d.camera.fovy) / 2. * std::numbers::pi / 180.);
    const double width = height * d.width / d.height;
    const glm::dvec3 topLeft = position - w + v * (height / 2.) - u * (width / 2.);
    std::vector<double> in{double(d.width), double(d.height), position.x, position.y, position.z, target.x,
                           target.y, target.z, up.x, up.y, up.z, double(d.camera.fovy)};
    const int c = inspection.call(probes::lookAt, in); // u, v, w, position, height, width, topLeft
    const std::string constructor = "PerspectiveCamera::PerspectiveCamera";
    inspection.add({.key = "lab4_screen", .lab = 2, .reference = Json::array({sx, sy})});
    inspection.add({.key = "lab4_u", .function = constructor, .lab = 4, .reference = vec(u), .student = values(c, 0, 3), .gives = "ray"});
    inspection.add({.key = "lab4_v", .function = constructor, .lab = 4, .reference = vec(v), .student = values(c, 3, 3), .gives = "ray"});
    inspection.add({.key = "lab4_w", .function = constructor, .lab = 4, .reference = vec(w), .student = values(c, 6, 3), .gives = "ray"});
    inspection.add({.key = "lab4_top_left", .function = constructor, .lab = 4, .reference = vec(topLeft), .student = values(c, 14, 3),
                    .gives = "ray"});
    pixel.ray = ReferenceRay{position, glm::normalize(topLeft + sx * width * u - sy * height * v - position)};
}

} // namespace

RAYLAB_REGISTER_INSPECTOR_STEP(InspectorStage::Ray, lookAtCamera);

} // namespace raylab::grader::inspector
