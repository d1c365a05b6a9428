#pragma once
// A change of origin. The renderer renders in a space whose origin is near the camera
// (src/render_space.h), so that far scenes keep float's precision where the rays start; each kind of
// object and of light says how it moves there (its `shifted`).

#include <glm/vec3.hpp>

namespace raylab {

// shift(p) is p - origin, computed in double (exact for two floats) and rounded once to float.
struct OriginShift {
    glm::vec3 origin{0.f};
    glm::vec3 operator()(const glm::vec3& p) const { return glm::vec3(glm::dvec3(p) - glm::dvec3(origin)); }
};

} // namespace raylab
