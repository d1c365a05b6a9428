#pragma once
// The objects of a picture and what the rays that miss them see.

#include "raylab/sphere_geometry.h"

#include <limits>
#include <vector>

namespace raylab {

struct Scene {
    std::vector<SphereGeometry> spheres;
    Color background{0.5f, 0.5f, 0.5f};

    // The nearest hit over all spheres with t in [tMin, tMax]; sets hit.object. The same order of
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
        return found;
    }

    // The nearest hit along the whole ray, t in [0, infinity).
    bool intersect(const Ray& ray, HitRecord& hit) const {
        return intersect(ray, 0.f, std::numeric_limits<float>::infinity(), hit);
    }
};

// The course's scene "tp1": one blue sphere of radius 1 at (0, 0, 3) on a grey background.
Scene makeTp1Scene();

} // namespace raylab
