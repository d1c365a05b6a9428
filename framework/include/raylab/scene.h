#pragma once
// The objects of a picture and what the rays that miss them see.

#include "raylab/sphere_geometry.h"

#include <limits>
#include <vector>

namespace raylab {

struct Scene {
    std::vector<SphereGeometry> spheres;
    Color background{0.5f, 0.5f, 0.5f};

    // The nearest hit over all spheres with t in [tMin, tMax]; sets hit.object.
    bool intersect(const Ray& ray, HitRecord& hit, float tMin = 0.f,
                   float tMax = std::numeric_limits<float>::infinity()) const;
};

// The scene as seen from `origin`: every centre moved by -origin. The renderer works in this
// camera-relative space (pbrt-v4's "camera-world" space) with the camera at (0, 0, 0): the lab
// code then handles hit points of the size of the distances to the camera, not of the world
// coordinates, so normals stay accurate 10^7 away from the world origin (docs/numerics.md).
Scene relativeTo(const Scene& scene, const glm::vec3& origin);

// The course's scene "tp1": one blue sphere of radius 1 at (0, 0, 3) on a grey background.
Scene makeTp1Scene();

} // namespace raylab
