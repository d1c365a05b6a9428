#pragma once
// A half-line origin + t * direction. The direction of a primary ray is normalized, so t is a distance.

#include <glm/vec3.hpp>

namespace raylab {

struct Ray {
    glm::vec3 origin{0.f};
    glm::vec3 direction{0.f, 0.f, 1.f};

    glm::vec3 at(float t) const { return origin + t * direction; }
};

} // namespace raylab
