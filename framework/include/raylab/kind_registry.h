#pragma once
// Kinds of objects and of lights by name, as integrators are (integrator_registry.h): a lab adds its
// own kind from its own file, and a scene file's `[[name]]` tables are its objects or its lights.
// Scene, the renderer, the shadow test, the studies and `raylab scene-format` then know it. A kind
// declares its parameters, with their types, defaults and ranges, and how to make one of them:
//
//   const KindRegistrar kTriangle("triangle", "a triangle, one side seen from both",
//       {{"a", ParameterType::Point, "a corner"}, {"b", ParameterType::Point, "the second corner"},
//        {"c", ParameterType::Point, "the third corner"},
//        {"color", ParameterType::Color, "its flat colour", Required::No}},
//       [](const KindValues& v) { return Triangle(v.point("a"), v.point("b"), v.point("c"), v.color("color")); });
//
// What `make` returns says which: a kind of object (shape.h) or of light (light.h). The scene file is
// checked against the declaration (each error names the file, the line and the key); what the
// declaration cannot say, `make` refuses with KindParameterError.

#include "raylab/scene.h"

#include <functional>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace raylab {

enum class ParameterType {
    Number,    // a finite number, in [min, max]
    Point,     // a position: 3 numbers, each at most 1e18 in magnitude (squared distances stay floats)
    Direction, // 3 finite numbers, not all 0 (not normalized: `make` decides)
    Color,     // 3 finite numbers, linear RGB; white when absent and not required
};

enum class Required : bool { No, Yes };

struct KindParameter {
    std::string key;
    ParameterType type = ParameterType::Number;
    std::string meaning; // a few words, for `raylab scene-format`
    Required required = Required::Yes;
    double min = -double(std::numeric_limits<float>::max()); // Number only
    double max = double(std::numeric_limits<float>::max());
    std::string rangeReason = ""; // why [min, max], said when a value is outside it
};

// A table's values, each of its declared type (a parameter not given and not required: absent).
class KindValues {
public:
    bool has(const std::string& key) const { return m_numbers.count(key) != 0 || m_vectors.count(key) != 0; }
    // A parameter's value; throws std::logic_error when it is absent (a required one never is).
    double number(const std::string& key) const;
    glm::vec3 point(const std::string& key) const { return vector(key); }
    glm::vec3 direction(const std::string& key) const { return vector(key); }
    // Absent: white.
    Color color(const std::string& key) const { return has(key) ? vector(key) : Color(1.f); }

    void set(const std::string& key, double value) { m_numbers[key] = value; }
    void set(const std::string& key, const glm::vec3& value) { m_vectors[key] = value; }

private:
    glm::vec3 vector(const std::string& key) const;
    std::map<std::string, double, std::less<>> m_numbers;
    std::map<std::string, glm::vec3, std::less<>> m_vectors;
};

// What `make` throws for values it refuses: `key` is the parameter at fault, or empty for the table.
class KindParameterError : public std::invalid_argument {
public:
    KindParameterError(std::string key, const std::string& problem) : std::invalid_argument(problem), m_key(std::move(key)) {}
    const std::string& key() const { return m_key; }

private:
    std::string m_key;
};

enum class KindRole { Object, Light };

struct RegisteredKind {
    std::string name; // the scene file's table, [[name]]
    std::string meaning;
    KindRole role = KindRole::Object;
    std::vector<KindParameter> parameters;
    // Adds what the values describe to the scene; throws KindParameterError, or
    // std::invalid_argument (the table's fault), for values it refuses.
    std::function<void(const KindValues&, Scene&)> add;
};

// Adds a kind; a name registered twice, of an object or a light, throws std::logic_error naming both places.
void registerKind(RegisteredKind kind, const char* file = __builtin_FILE(), unsigned line = __builtin_LINE());

// Every registered kind (the framework's sphere, plane and point light, and the labs'), sorted by name.
std::vector<const RegisteredKind*> registeredKinds();
// The kind of that name; nullptr when there is none.
const RegisteredKind* findKind(std::string_view name);

// Registers at static initialisation: `make` turns the values into an object or a light of the kind
// (its return type), which the course's lab.toml lists in `shapes` or `lights`.
struct KindRegistrar {
    template <class Make>
    KindRegistrar(std::string name, std::string meaning, std::vector<KindParameter> parameters, Make make,
                  const char* file = __builtin_FILE(), unsigned line = __builtin_LINE()) {
        using Kind = std::invoke_result_t<Make, const KindValues&>;
        static_assert(ShapeKind<Kind> || LightKind<Kind>,
                      "`make` must return an object (raylab/shape.h) or a light (raylab/light.h)");
        static_assert(SceneShapeKind<Kind> || SceneLightKind<Kind>,
                      "a kind of the course's lab lists in its lab.toml's `shapes` or `lights` (raylab/scene.h)");
        registerKind({std::move(name), std::move(meaning), ShapeKind<Kind> ? KindRole::Object : KindRole::Light,
                      std::move(parameters), [make](const KindValues& values, Scene& scene) { scene.add(make(values)); }},
                     file, line);
    }
};

} // namespace raylab
