// Lab 4's rows of the pixel inspector (grader/inspector/inspector_steps.h): the lookAt camera's frame
// and its screen's top-left corner, asked of the constructor, and the reference's ray through the
// pixel centre, which the rows of what it meets (lab 3's, lab 6's) follow. The handout's frame:
// w = normalize(position - target), u = normalize(cross(up, w)), v = cross(w, u), the screen at 1.
#include "answers.h"
#include "grader/inspector/inspector_steps.h"
#include "probes.h"

namespace raylab::grader::inspector {

namespace {

void lookAtCamera(PixelContext& pixel, Inspection& inspection) {
    const SceneDescription& d = pixel.scene;
    if (d.samples != 1 || !d.camera.lookAt || pixel.ray) return;
    const double sx = (pixel.x + 0.5) / d.width, sy = (pixel.y + 0.5) / d.height;
    const glm::dvec3 position(d.camera.position), target(d.camera.target), up(d.camera.up);
    const lab4::Frame frame = lab4::lookAt(position, target, up);
    const lab4::Viewport screen = lab4::viewport(d.camera.fovy, d.width, d.height);
    const probes::LookAtCamera camera{d.width, d.height, position, target, up, d.camera.fovy};
    const int c = inspection.call(probes::lookAt(camera));
    const std::string constructor = "PerspectiveCamera::PerspectiveCamera";
    inspection.add({.key = "lab4_screen", .lab = 2, .reference = Json::array({sx, sy})});
    inspection.add({.key = "lab4_u", .function = constructor, .lab = 4, .reference = shown(frame.u),
                    .student = answerOf(probes::lookAt, c, &probes::BuiltCamera::u), .gives = "ray"});
    inspection.add({.key = "lab4_v", .function = constructor, .lab = 4, .reference = shown(frame.v),
                    .student = answerOf(probes::lookAt, c, &probes::BuiltCamera::v), .gives = "ray"});
    inspection.add({.key = "lab4_w", .function = constructor, .lab = 4, .reference = shown(frame.w),
                    .student = answerOf(probes::lookAt, c, &probes::BuiltCamera::w), .gives = "ray"});
    inspection.add({.key = "lab4_top_left", .function = constructor, .lab = 4, .reference = shown(lab4::topLeft(frame, screen)),
                    .student = answerOf(probes::lookAt, c, &probes::BuiltCamera::topLeft), .gives = "ray"});
    pixel.ray = ReferenceRay{position, lab4::direction(frame, screen, sx, sy)};
}

} // namespace

RAYLAB_REGISTER_INSPECTOR_STEP(InspectorStage::Ray, lookAtCamera);

} // namespace raylab::grader::inspector
