#pragma once
// How Scene keeps its lights (scene.h): the point lights in Scene::lights, each other kind a lab
// brings in an array of its own. Nothing here is a lab's to write.

#include "raylab/detail/kind_list.h"
#include "raylab/light.h"
#include "raylab/shape.h"

#include <concepts>
#include <tuple>
#include <vector>

namespace raylab {

// What a kind of light provides (light.h). Not a Shape: a scene file's table is one or the other.
template <class Kind>
concept LightKind = !std::derived_from<Kind, Shape> && std::copy_constructible<Kind> &&
                    requires(const Kind& light, const OriginShift& shift) {
                        { light.shifted(shift) } -> std::same_as<Kind>;
                    };

// An array for each kind of the list after the first (PointLight, whose array is Scene::lights).
template <class List> struct OtherLightsOf;
template <class First, class... Rest> struct OtherLightsOf<KindList<First, Rest...>> {
    using type = std::tuple<std::vector<Rest>...>;
};

} // namespace raylab
