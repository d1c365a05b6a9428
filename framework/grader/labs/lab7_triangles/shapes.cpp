// Lab 7's kind of object under its scene-file name, [[triangle]] (its class: labs/lab7_triangles/shapes.h).
#include "raylab/kind_registry.h"

#include <glm/geometric.hpp>

namespace raylab {
namespace {

// Whether the corners are on one line. In double, where the products of the float corners' differences
// are (nearly) exact: a thin triangle is not taken for a line.
bool onOneLine(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    return glm::cross(glm::dvec3(b) - glm::dvec3(a), glm::dvec3(c) - glm::dvec3(a)) == glm::dvec3(0.);
}

const KindRegistrar kTriangle(
    "triangle", "a triangle with a flat colour, its normal by the right-hand rule from a, b, c (lab 7)",
    {{"a", ParameterType::Point, "its first corner"},
     {"b", ParameterType::Point, "its second corner"},
     {"c", ParameterType::Point, "its third corner"},
     {"color", ParameterType::Color, "its colour", Required::No}},
    [](const KindValues& v) {
        if (onOneLine(v.point("a"), v.point("b"), v.point("c")))
            throw KindParameterError("", "its corners a, b, c are on one line: it has no area and no normal");
        return Triangle(v.point("a"), v.point("b"), v.point("c"), v.color("color"));
    });

} // namespace
} // namespace raylab
