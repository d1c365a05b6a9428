#pragma once
// Kinds of objects by name, as integrators are (integrator_registry.h): a lab adds its own kind from
// its own file, and a scene file's `[[name]]` tables are its objects. Scene, the renderer, the shadow
// test, the studies and `raylab scene-format` then know it. A kind declares its parameters, with their
// types, defaults and ranges, and how to make an object of them:
//
//   const ShapeKindRegistrar kTriangle("triangle", "a triangle, one side seen from both",
//       {{"a", ParameterType::Point, "a corner"}, {"b", ParameterType::Point, "the second corner"},
//        {"c", ParameterType::Point, "the third corner"},
//        {"color", ParameterType::Color, "its flat colour", Required::No}},
//       [](const ShapeValues& v) { return Triangle(v.point("a"), v.point("b"), v.point("c"), v.color("color")); });
//
// The scene file is checked against the declaration (each error names the file, the line and the
// key); what the declaration cannot say, `make` refuses with ShapeParameterError. The kind itself is
// a class as shape.h says.

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

struct ShapeParameter {
    std::string key;
    ParameterType type = ParameterType::Number;
    std::string meaning; // a few words, for `raylab scene-format`
    Required required = Required::Yes;
    double min = -double(std::numeric_limits<float>::max()); // Number only
    double max = double(std::numeric_limits<float>::max());
    std::string rangeReason = ""; // why [min, max], said when a value is outside it
};

// A table's values, each of its declared type (a parameter not given and not required: absent).
class ShapeValues {
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
class ShapeParameterError : public std::invalid_argument {
public:
    ShapeParameterError(std::string key, const std::string& problem) : std::invalid_argument(problem), m_key(std::move(key)) {}
    const std::string& key() const { return m_key; }

private:
    std::string m_key;
};

struct RegisteredShapeKind {
    std::string name; // the scene file's table, [[name]]
    std::string meaning;
    std::vector<ShapeParameter> parameters;
    // Adds the object the values describe to the scene; throws ShapeParameterError, or
    // std::invalid_argument (the table's fault), for values it refuses.
    std::function<void(const ShapeValues&, Scene&)> add;
};

// Adds a kind; a name registered twice throws std::logic_error naming both places.
void registerShapeKind(RegisteredShapeKind kind, const char* file = __builtin_FILE(), unsigned line = __builtin_LINE());

// Every registered kind (the framework's sphere and plane, and the labs'), sorted by name.
std::vector<const RegisteredShapeKind*> registeredShapeKinds();
// The kind of that name; nullptr when there is none.
const RegisteredShapeKind* findShapeKind(std::string_view name);

// Registers at static initialisation: `make` turns the values into an object of the kind (its return type).
struct ShapeKindRegistrar {
    template <class Make>
    ShapeKindRegistrar(std::string name, std::string meaning, std::vector<ShapeParameter> parameters, Make make,
                       const char* file = __builtin_FILE(), unsigned line = __builtin_LINE()) {
        using Kind = std::invoke_result_t<Make, const ShapeValues&>;
        static_assert(ShapeKind<Kind>, "`make` must return an object of a kind of shape (raylab/shape.h)");
        static_assert(SceneShapeKind<Kind>, "a kind of the course's lab lists in its lab.toml's `shapes` (raylab/scene.h)");
        registerShapeKind({std::move(name), std::move(meaning), std::move(parameters),
                           [make](const ShapeValues& values, Scene& scene) { scene.add(make(values)); }},
                          file, line);
    }
};

} // namespace raylab
