#pragma once
// A closed list of kinds (of objects, of lights), known when Scene is compiled (raylab/scene.h).
// Nothing here is a lab's to write.

#include <type_traits>

namespace raylab {

template <class... Kinds> struct KindList {};

template <class Kind, class... Kinds> constexpr bool isOneOf(KindList<Kinds...>) { return (std::is_same_v<Kind, Kinds> || ...); }

// Kind's place in the list (the list's length when it is not in it).
template <class Kind, class... Kinds> constexpr unsigned char kindIndex(KindList<Kinds...>) {
    unsigned char index = 0;
    (void)((std::is_same_v<Kind, Kinds> || (++index, false)) || ...);
    return index;
}

} // namespace raylab
