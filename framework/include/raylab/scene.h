#pragma once
// The objects of a picture, its lights, and what the rays that miss every object see.

#include "raylab/detail/light_groups.h"
#include "raylab/detail/shape_groups.h"
#include "raylab/light.h"
#include "raylab/plane.h"
#include "raylab/sphere_geometry.h"

#include <limits>
#include <tuple>
#include <type_traits>
#include <vector>

// The kinds of objects and of lights a scene may hold: the framework's, then those the course's labs
// bring (each lab.toml's `shapes` and `lights`, declared in its folder's shapes.h and lights.h): CMake
// writes the lists into raylab/course_kinds.h. Closed lists in each build, so that Scene tests every
// kind of object inline.
#if __has_include("raylab/course_kinds.h")
#include "raylab/course_kinds.h"
#else
#define RAYLAB_COURSE_SHAPES
#define RAYLAB_COURSE_LIGHTS
#endif

namespace raylab {

using SceneShapeKinds = KindList<SphereGeometry, Plane RAYLAB_COURSE_SHAPES>;
template <class Kind> concept SceneShapeKind = ShapeKind<Kind> && isOneOf<Kind>(SceneShapeKinds{});

using SceneLightKinds = KindList<PointLight RAYLAB_COURSE_LIGHTS>;
template <class Kind> concept SceneLightKind = LightKind<Kind> && isOneOf<Kind>(SceneLightKinds{});

struct Scene {
    std::vector<PointLight> lights; // the point lights; none: nothing casts a shadow ray
    Color background{0.5f, 0.5f, 0.5f};

    // Adds an object of any kind (shape.h): scene.add(SphereGeometry(centre, radius, colour)).
    template <SceneShapeKind Kind> void add(const Kind& object) {
        group<Kind>().objects.push_back(object);
        withKind(group<Kind>().objects.back());
    }
    // Adds a light of any kind (light.h); a PointLight goes to `lights`.
    template <SceneLightKind Kind> void add(const Kind& light) { lightsOf<Kind>().push_back(light); }
    // The lights of one kind, in the order added: lightsOf<PointLight>() is `lights`.
    template <SceneLightKind Kind> const std::vector<Kind>& lightsOf() const {
        return const_cast<Scene&>(*this).lightsOf<Kind>();
    }
    // Calls f(lights) for each kind's array of lights, in the order of SceneLightKinds.
    template <class F> void forEachLightKind(F&& f) const {
        f(lights);
        std::apply([&](const auto&... group) { (f(group), ...); }, m_otherLights);
    }
    // The objects of one kind, in the order added.
    template <SceneShapeKind Kind> const std::vector<Kind>& all() const { return std::get<ShapesOf<Kind>>(m_groups).objects; }
    // Replaces the objects of one kind (the other kinds' stay).
    template <SceneShapeKind Kind> void setAll(std::vector<Kind> objects) {
        for (Kind& object : objects) withKind(object);
        group<Kind>().objects = std::move(objects);
    }
    // Calls f(group) for each kind's ShapesOf<Kind>, in the order of SceneShapeKinds.
    template <class F> void forEachGroup(F&& f) const {
        std::apply([&](const auto&... group) { (f(group), ...); }, m_groups);
    }
    std::size_t objectCount() const {
        std::size_t count = 0;
        forEachGroup([&](const auto& group) { count += group.objects.size(); });
        return count;
    }

    // The nearest hit over all objects with t in [tMin, tMax]; sets hit.object. The same order of
    // parameters as SphereGeometry::intersect. Inline, and each kind's code with it: the
    // integrators call it once per ray (docs/performance.md).
    bool intersect(const Ray& ray, float tMin, float tMax, HitRecord& hit) const {
        bool found = false;
        std::apply([&](const auto&... group) { (group.intersectAll(ray, tMin, tMax, hit, found), ...); }, m_groups);
        return found;
    }

    // The nearest hit along the whole ray, t in [0, infinity).
    bool intersect(const Ray& ray, HitRecord& hit) const {
        return intersect(ray, 0.f, std::numeric_limits<float>::infinity(), hit);
    }

    // The shadow test: whether some object meets the ray at a t strictly between tMin and tMax.
    // It stops at the first object met, where intersect has to try them all for the nearest, and
    // it fills no hit. Open at both ends: the point the ray leaves (t = tMin) and the light it
    // goes to (t = tMax) do not block it. Counted in RenderStats::shadowRays.
    bool occluded(const Ray& ray, float tMin, float tMax) const;

private:
    template <SceneShapeKind Kind> static void withKind(Kind& object) {
        static_cast<Shape&>(object).m_kind = kindIndex<Kind>(SceneShapeKinds{});
    }
    template <SceneShapeKind Kind> ShapesOf<Kind>& group() { return std::get<ShapesOf<Kind>>(m_groups); }
    template <SceneLightKind Kind> std::vector<Kind>& lightsOf() {
        if constexpr (std::is_same_v<Kind, PointLight>) return lights;
        else return std::get<std::vector<Kind>>(m_otherLights);
    }

    ShapeGroupsOf<SceneShapeKinds>::type m_groups;
    OtherLightsOf<SceneLightKinds>::type m_otherLights;
};

inline glm::vec3 Shape::computeNormal(const glm::vec3& p) const { return normalOfKind(*this, m_kind, p, SceneShapeKinds{}); }

// The course's scene "tp1": one blue sphere of radius 1 at (0, 0, 3) on a grey background.
Scene makeTp1Scene();

} // namespace raylab
