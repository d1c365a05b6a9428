#include "raylab/kind_registry.h"

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

// A light's intensity times its colour is stored as float.
const double kFloatMax = double(std::numeric_limits<float>::max());

// The framework's own kinds. Registered with the registry itself, not by registrars in their own
// files: nothing else names those files' registrars, so a static library's link would leave them out.
void addFrameworkKinds(NameRegistry<RegisteredKind>& registry) {
    const SourcePlace here = SourcePlace::here();
    registry.add("sphere",
                 {"sphere", "a sphere with a flat colour (lab 3)", KindRole::Object,
                  {{"center", ParameterType::Point, "its centre"},
                   {"radius", ParameterType::Number, "its radius", Required::Yes, kMinRadius, kMaxRadius,
                    "its square must stay a normal float"},
                   {"color", ParameterType::Color, "its colour", Required::No}},
                  [](const KindValues& v, Scene& scene) {
                      scene.add(SphereGeometry(v.point("center"), float(v.number("radius")), v.color("color")));
                  }},
                 here);
    // A point of the plane, or its offset: the plane dot(n, x) = offset of the unit normal n
    // (docs/conventions.md).
    registry.add("plane",
                 {"plane", "an infinite plane with a flat colour", KindRole::Object,
                  {{"normal", ParameterType::Direction, "its normal, normalized when read"},
                   {"point", ParameterType::Point, "a point of the plane; or, instead of it, offset", Required::No},
                   {"offset", ParameterType::Number, "the plane dot(n, x) = offset of the unit normal n", Required::No,
                    -1e18, 1e18, "so that squared distances stay within float"},
                   {"color", ParameterType::Color, "its colour", Required::No}},
                  [](const KindValues& v, Scene& scene) {
                      if (v.has("point") == v.has("offset"))
                          throw KindParameterError("", "a plane needs a normal, and either a point or an offset");
                      const glm::vec3 normal = v.direction("normal");
                      const glm::vec3 point = v.has("point") ? v.point("point")
                                                             : glm::vec3(v.number("offset") * glm::normalize(glm::dvec3(normal)));
                      scene.add(Plane(point, normal, v.color("color")));
                  }},
                 here);
    // Its radiant intensity is intensity * color (docs/conventions.md, "Lights").
    registry.add("light",
                 {"light", "a point light", KindRole::Light,
                  {{"position", ParameterType::Point, "where it shines from"},
                   {"intensity", ParameterType::Number, "its radiant intensity", Required::Yes, 0., kFloatMax,
                    "an intensity is not negative, and fits a float"},
                   {"color", ParameterType::Color, "its colour, times the intensity", Required::No}},
                  [](const KindValues& v, Scene& scene) {
                      const Color color = v.color("color");
                      if (!(color.r >= 0.f && color.g >= 0.f && color.b >= 0.f))
                          throw KindParameterError("color", showVector(color) + ": a light's colour has no negative channel");
                      const Color radiant = float(v.number("intensity")) * color;
                      if (!std::isfinite(radiant.r) || !std::isfinite(radiant.g) || !std::isfinite(radiant.b))
                          throw KindParameterError("color", "intensity * color overflows float (" + showVector(radiant) + ")");
                      scene.add(PointLight{v.point("position"), radiant});
                  }},
                 here);
}

// Built on first use: registrars run during static initialisation, in any order of files.
NameRegistry<RegisteredKind>& kinds() {
    static NameRegistry<RegisteredKind> registry("kind of object or light");
    static const bool framework = (addFrameworkKinds(registry), true);
    (void)framework;
    return registry;
}

} // namespace

double KindValues::number(const std::string& key) const {
    const auto at = m_numbers.find(key);
    if (at == m_numbers.end()) throw std::logic_error("no number '" + key + "' among the values");
    return at->second;
}

glm::vec3 KindValues::vector(const std::string& key) const {
    const auto at = m_vectors.find(key);
    if (at == m_vectors.end()) throw std::logic_error("no vector '" + key + "' among the values");
    return at->second;
}

void registerKind(RegisteredKind kind, const char* file, unsigned line) {
    const std::string name = kind.name;
    kinds().add(name, std::move(kind), {file, line});
}

std::vector<const RegisteredKind*> registeredKinds() {
    std::vector<const RegisteredKind*> all;
    for (const std::string& name : kinds().names()) all.push_back(&kinds().find(name)->value);
    return all;
}

const RegisteredKind* findKind(std::string_view name) {
    const auto* entry = kinds().find(name);
    return entry != nullptr ? &entry->value : nullptr;
}

} // namespace raylab
