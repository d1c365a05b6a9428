#pragma once
// The objects of a picture and what the rays that miss them see.

#include "raylab/sphere_geometry.h"

#include <limits>
#include <vector>

namespace raylab {

struct Scene {
    std::vector<SphereGeometry> spheres;
    Color background{0.5f, 0.5f, 0.5f};

    // The nearest hit over all spheres with t in [tMin, tMax]; sets hit.object. Inline: the
    // integrators call it once per ray.
    bool intersect(const Ray& ray, HitRecord& hit, float tMin = 0.f,
                   float tMax = std::numeric_limits<float>::infinity()) const {
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
};

// Large world coordinates (docs/numerics.md, section 9). Floats 10^7 from the origin are 1 apart,
// so hit points there, and the normals taken from them, are off by up to 1. The renderer therefore
// works in a render space whose origin is a point of a 1024-unit grid near the camera (a "floating
// origin"): the camera stays within 512 of it, and what the camera sees keeps about 6e-5 of
// precision wherever it is. A camera within 512 of the world origin renders in world coordinates,
// exactly as before, so every lab sees the positions its figures were made with.
inline constexpr float kRenderCell = 1024.f;

// The render-space origin for a camera at `cameraPosition`: each coordinate rounded to a multiple
// of kRenderCell (exact in float).
glm::vec3 renderOrigin(const glm::vec3& cameraPosition);

// `point` - `origin`, taken in double (exact for two floats) and rounded once to float.
glm::vec3 relativeTo(const glm::vec3& point, const glm::vec3& origin);

// The scene with every centre moved by -origin.
Scene relativeTo(const Scene& scene, const glm::vec3& origin);

// The course's scene "tp1": one blue sphere of radius 1 at (0, 0, 3) on a grey background.
Scene makeTp1Scene();

} // namespace raylab
