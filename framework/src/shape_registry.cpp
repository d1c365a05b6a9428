#include "raylab/shape_registry.h"

#include "src/name_registry.h"
#include "src/text.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace raylab {

namespace {

// The intersection squares the radius and the distance from the ray's origin to the centre in
// float (docs/numerics.md, section 2): both squares must stay normal floats.
const double kMinRadius = std::sqrt(double(std::numeric_limits<float>::min())); // 1.08e-19
const double kMaxRadius = std::sqrt(double(std::numeric_limits<float>::max())); // 1.84e19

// The framework's own kinds. Registered with the registry itself, not by registrars in their own
// files: nothing else names those files' registrars, so a static library's link would leave them out.
void addFrameworkKinds(NameRegistry<RegisteredShapeKind>& registry) {
    const SourcePlace here = SourcePlace::here();
    registry.add("sphere",
                 {"sphere", "a sphere with a flat colour (lab 3)",
                  {{"center", ParameterType::Point, "its centre"},
                   {"radius", ParameterType::Number, "its radius", Required::Yes, kMinRadius, kMaxRadius,
                    "its square must stay a normal float"},
                   {"color", ParameterType::Color, "its colour", Required::No}},
                  [](const ShapeValues& v, Scene& scene) {
                      scene.add(SphereGeometry(v.point("center"), float(v.number("radius")), v.color("color")));
                  }},
                 here);
    // A point of the plane, or its offset: the plane dot(n, x) = offset of the unit normal n
    // (docs/conventions.md).
    registry.add("plane",
                 {"plane", "an infinite plane with a flat colour",
                  {{"normal", ParameterType::Direction, "its normal, normalized when read"},
                   {"point", ParameterType::Point, "a point of the plane; or, instead of it, offset", Required::No},
                   {"offset", ParameterType::Number, "the plane dot(n, x) = offset of the unit normal n", Required::No,
                    -1e18, 1e18, "so that squared distances stay within float"},
                   {"color", ParameterType::Color, "its colour", Required::No}},
                  [](const ShapeValues& v, Scene& scene) {
                      if (v.has("point") == v.has("offset"))
                          throw ShapeParameterError("", "a plane needs a normal, and either a point or an offset");
                      const glm::vec3 normal = v.direction("normal");
                      const glm::vec3 point = v.has("point") ? v.point("point")
                                                             : glm::vec3(v.number("offset") * glm::normalize(glm::dvec3(normal)));
                      scene.add(Plane(point, normal, v.color("color")));
                  }},
                 here);
}

// Built on first use: registrars run during static initialisation, in any order of files.
NameRegistry<RegisteredShapeKind>& kinds() {
    static NameRegistry<RegisteredShapeKind> registry("kind of object");
    static const bool framework = (addFrameworkKinds(registry), true);
    (void)framework;
    return registry;
}

} // namespace

double ShapeValues::number(const std::string& key) const {
    const auto at = m_numbers.find(key);
    if (at == m_numbers.end()) throw std::logic_error("no number '" + key + "' among the values");
    return at->second;
}

glm::vec3 ShapeValues::vector(const std::string& key) const {
    const auto at = m_vectors.find(key);
    if (at == m_vectors.end()) throw std::logic_error("no vector '" + key + "' among the values");
    return at->second;
}

void registerShapeKind(RegisteredShapeKind kind, const char* file, unsigned line) {
    const std::string name = kind.name;
    kinds().add(name, std::move(kind), {file, line});
}

std::vector<const RegisteredShapeKind*> registeredShapeKinds() {
    std::vector<const RegisteredShapeKind*> all;
    for (const std::string& name : kinds().names()) all.push_back(&kinds().find(name)->value);
    return all;
}

const RegisteredShapeKind* findShapeKind(std::string_view name) {
    const auto* entry = kinds().find(name);
    return entry != nullptr ? &entry->value : nullptr;
}

} // namespace raylab
