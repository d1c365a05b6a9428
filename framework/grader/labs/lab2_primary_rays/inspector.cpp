// Lab 2's rows of the pixel inspector (grader/inspector/inspector_steps.h): the pixel centre's screen
// point and the default camera's ray through it, asked of generateRay. The reference's camera is the
// handout's default frame (u = (-1, 0, 0), v = (0, 1, 0), w = (0, 0, -1)), the screen at distance 1.
#include "answers.h"
#include "grader/inspector/inspector_steps.h"
#include "probes.h"

namespace raylab::grader::inspector {

namespace {

void defaultCamera(PixelContext& pixel, Inspection& inspection) {
    const SceneDescription& d = pixel.scene;
    if (d.samples != 1 || d.camera.lookAt || pixel.ray) return; // lab 4's camera, lab 5's samples
    const double sx = (pixel.x + 0.5) / d.width, sy = (pixel.y + 0.5) / d.height;
    const glm::dvec3 position(d.camera.position);
    const ReferenceRay ray{position, lab2::direction(lab2::defaultFrame(position), lab2::viewport(d.camera.fovy, d.width, d.height), sx, sy)};
    const probes::DefaultFrameCamera camera{d.width, d.height, d.camera.fovy, position};
    const int c = inspection.call(probes::generateRay(camera, sx, sy));
    inspection.add({.key = "lab2_screen", .lab = 2, .reference = Json::array({sx, sy})});
    inspection.add({.key = "lab2_origin", .function = "PerspectiveCamera::generateRay", .lab = 2, .reference = shown(ray.origin),
                    .student = answerOf(probes::generateRay, c, &probes::PrimaryRay::origin), .gives = "ray"});
    inspection.add({.key = "lab2_direction", .function = "PerspectiveCamera::generateRay", .lab = 2, .reference = shown(ray.direction),
                    .student = answerOf(probes::generateRay, c, &probes::PrimaryRay::direction), .gives = "ray"});
    pixel.ray = ray;
}

} // namespace

RAYLAB_REGISTER_INSPECTOR_STEP(InspectorStage::Ray, defaultCamera);

} // namespace raylab::grader::inspector
