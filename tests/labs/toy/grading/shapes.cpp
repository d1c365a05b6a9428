// The toy lab's kind of object under its scene-file name, [[toy_square]] (its class: labs/<lab>/shapes.h).
#include "raylab/kind_registry.h"

namespace raylab {
namespace {

const KindRegistrar kToySquare(
    "toy_square", "a square facing the default camera (the toy lab)",
    {{"center", ParameterType::Point, "its centre"},
     {"side", ParameterType::Number, "the length of its sides", Required::Yes, 1e-6, 1e6, "a square one can see"},
     {"color", ParameterType::Color, "its colour", Required::No}},
    [](const KindValues& v) { return ToySquare(v.point("center"), float(v.number("side")), v.color("color")); });

} // namespace
} // namespace raylab
