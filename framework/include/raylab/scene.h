#pragma once
// The objects of a picture, its lights, and what the rays that miss every object see.

#include "raylab/light.h"
#include "raylab/plane.h"
#include "raylab/sphere_geometry.h"

#include <limits>
#include <vector>

namespace raylab {

struct Scene {
    std::vector<SphereGeometry> spheres;
    std::vector<Plane> planes;
    std::vector<PointLight> lights; // none: nothing casts a shadow ray
    Color background{0.5f, 0.5f, 0.5f};

    // The nearest hit over all objects with t in [tMin, tMax]; sets hit.object. The same order of
    // parameters as SphereGeometry::intersect. Inline: the integrators call it once per ray.
    bool intersect(const Ray& ray, float tMin, float tMax, HitRecord& hit) const {
        bool found = false;
        for (const SphereGeometry& sphere : spheres) {
            // Each hit narrows the interval, so the last one found is the nearest.
            if (sphere.intersect(ray, tMin, tMax, hit)) {
                found = true;
                tMax = hit.t;
                hit.object = &sphere;
            }
        }
        for (const Plane& plane : planes) {
            if (plane.intersect(ray, tMin, tMax, hit)) {
                found = true;
                tMax = hit.t;
                hit.object = &plane;
            }
        }
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
};

inline glm::vec3 Shape::computeNormal(const glm::vec3& p) const {
    if (m_kind == Kind::Sphere) return static_cast<const SphereGeometry*>(this)->computeNormal(p);
    return static_cast<const Plane*>(this)->computeNormal(p);
}

// The course's scene "tp1": one blue sphere of radius 1 at (0, 0, 3) on a grey background.
Scene makeTp1Scene();

} // namespace raylab
