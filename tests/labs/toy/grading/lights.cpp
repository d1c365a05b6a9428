// The toy lab's kind of light under its scene-file name, [[toy_lamp]] (its class: labs/<lab>/lights.h).
#include "raylab/kind_registry.h"

namespace raylab {
namespace {

const KindRegistrar kToyLamp("toy_lamp", "a lamp that tints the surfaces facing it (the toy lab)",
                             {{"position", ParameterType::Point, "where it stands"},
                              {"tint", ParameterType::Color, "the colour it gives what faces it", Required::No}},
                             [](const KindValues& v) {
                                 if (v.color("tint") == Color(0.f)) throw KindParameterError("tint", "a black lamp tints nothing");
                                 return ToyLamp{v.point("position"), v.color("tint")};
                             });

} // namespace
} // namespace raylab
