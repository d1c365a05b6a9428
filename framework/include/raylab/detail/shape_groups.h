#pragma once
// How Scene keeps its objects (scene.h): one array per kind, each tested by its kind's own code,
// inline. Nothing here is a lab's to write.

#include "raylab/detail/kind_list.h"
#include "raylab/hit_record.h"
#include "raylab/ray.h"
#include "raylab/shape.h"

#include <concepts>
#include <limits>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace raylab {

// What a kind of object provides (shape.h).
template <class Kind>
concept ShapeKind = std::derived_from<Kind, Shape> && std::copy_constructible<Kind> &&
                    requires(const Kind& s, const Ray& ray, float t, HitRecord& hit, const glm::vec3& p, const OriginShift& shift) {
                        { s.intersect(ray, t, t, hit) } -> std::same_as<bool>;
                        { s.hits(ray, t, t) } -> std::same_as<bool>;
                        { s.computeNormal(p) } -> std::same_as<glm::vec3>;
                        { s.shifted(shift) } -> std::same_as<Kind>;
                    };

// The normal at p of `shape`, whose kind is number `kind` of Kind, Rest...: that kind's computeNormal,
// called directly, as Scene::intersect calls each kind's intersect (the first kind's costs one
// comparison); NaN for a kind not in the list.
template <class Kind, class... Rest> glm::vec3 normalOfKind(const Shape& shape, unsigned kind, const glm::vec3& p) {
    if (kind == 0) return static_cast<const Kind&>(shape).computeNormal(p);
    if constexpr (sizeof...(Rest) == 0) return glm::vec3(std::numeric_limits<float>::quiet_NaN());
    else return normalOfKind<Rest...>(shape, kind - 1, p);
}
template <class... Kinds> glm::vec3 normalOfKind(const Shape& shape, unsigned kind, const glm::vec3& p, KindList<Kinds...>) {
    return normalOfKind<Kinds...>(shape, kind, p);
}

// The objects of one kind.
template <ShapeKind Kind> struct ShapesOf {
    std::vector<Kind> objects;

    // The nearest hit among them with t in [tMin, tMax], if any: narrows tMax to its t, fills hit
    // and sets found.
    void intersectAll(const Ray& ray, float tMin, float& tMax, HitRecord& hit, bool& found) const {
        for (const Kind& object : objects) {
            // Each hit narrows the interval, so the last one found is the nearest.
            if (object.intersect(ray, tMin, tMax, hit)) {
                found = true;
                tMax = hit.t;
                hit.object = &object;
            }
        }
    }
    // Whether one of them meets the ray with t in [tMin, tMax].
    bool hitsAny(const Ray& ray, float tMin, float tMax) const {
        for (const Kind& object : objects)
            if (object.hits(ray, tMin, tMax)) return true;
        return false;
    }
    // The object whose surface is nearest to p, and how far (infinity and nullptr: none, or a kind
    // without distanceTo).
    std::pair<float, const Shape*> nearestSurface(const glm::vec3& p) const {
        std::pair<float, const Shape*> nearest{std::numeric_limits<float>::infinity(), nullptr};
        if constexpr (requires(const Kind& s) { { s.distanceTo(p) } -> std::same_as<float>; })
            for (const Kind& object : objects)
                if (const float d = object.distanceTo(p); d < nearest.first) nearest = {d, &object};
        return nearest;
    }
};

// One ShapesOf a kind, for each kind of the list.
template <class List> struct ShapeGroupsOf;
template <class... Kinds> struct ShapeGroupsOf<KindList<Kinds...>> {
    using type = std::tuple<ShapesOf<Kinds>...>;
};

} // namespace raylab
