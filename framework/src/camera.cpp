#include "raylab/perspective_camera.h"
#include "src/text.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

namespace raylab {

namespace {

bool isFinite(const glm::vec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

} // namespace

// Pixel centres (i + 0.5) / W are computed in float, with a relative rounding error of 2^-24: for
// W above 2^20 they drift by more than 1/32 pixel, and from 2^24 on neighbouring columns share one
// centre (measured by `raylab numerics`, docs/numerics.md).
constexpr int kMaxImageSide = 1 << 20;

BaseCamera::BaseCamera(int width, int height) : m_width(width), m_height(height) {
    if (width < 1 || height < 1)
        throw std::invalid_argument("camera: image size " + std::to_string(width) + " x " + std::to_string(height) +
                                    " has no pixel; width and height must be at least 1");
    if (width > kMaxImageSide || height > kMaxImageSide)
        throw std::invalid_argument("camera: image size " + std::to_string(width) + " x " + std::to_string(height) +
                                    ": a side above " + std::to_string(kMaxImageSide) +
                                    " pixels puts the float pixel centres (i + 0.5) / W more than 1/32 pixel off");
}

PerspectiveCamera::PerspectiveCamera(int width, int height, float fovyDegrees)
    : BaseCamera(width, height), m_fovy(fovyDegrees) {
    // tan(fovy / 2) is 0 at 0 degrees and infinite at 180: no screen either way.
    if (!(fovyDegrees > 0.f && fovyDegrees < 180.f))
        throw std::invalid_argument("camera: fovy = " + showNumber(fovyDegrees) +
                                    " degrees has no meaning; it must be strictly between 0 and 180");
    updateViewport();
}

PerspectiveCamera::PerspectiveCamera(int width, int height, const glm::vec3& position, float fovyDegrees)
    : PerspectiveCamera(width, height, fovyDegrees) {
    m_position = position;
    updateViewport();
}

void checkLookAtParameters(const glm::vec3& position, const glm::vec3& target, const glm::vec3& up) {
    if (!isFinite(position)) throw std::invalid_argument("camera: position = " + showVector(position) + " is not finite");
    if (!isFinite(target)) throw std::invalid_argument("camera: look_at = " + showVector(target) + " is not finite");
    if (!isFinite(up)) throw std::invalid_argument("camera: up = " + showVector(up) + " is not finite");
    const glm::vec3 view = target - position;
    if (!(glm::length(view) > 0.f))
        throw std::invalid_argument("camera: position = look_at = " + showVector(position) +
                                    ": the camera looks nowhere; move the target away from the position");
    if (!isFinite(glm::normalize(view)))
        throw std::invalid_argument("camera: look_at - position = " + showVector(view) +
                                    " overflows float: the camera looks nowhere; bring position and look_at closer");
    const float upLength = glm::length(up);
    if (!(upLength > 0.f) || !isFinite(glm::normalize(up)))
        throw std::invalid_argument("camera: up = " + showVector(up) + " has no direction (its length is " +
                                    showNumber(upLength) + "); give a vector such as (0, 1, 0)");
    // |cross(up, view)| = |up| |view| sin(angle): below 1e-6 the basis would be noise.
    if (glm::length(glm::cross(up, glm::normalize(view))) <= 1e-6f * upLength)
        throw std::invalid_argument("camera: up = " + showVector(up) + " is parallel to the view direction " +
                                    showVector(glm::normalize(view)) + ", so it gives no vertical; choose another up");
}

} // namespace raylab
