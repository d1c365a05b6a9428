#pragma once
// What an intersection test tells about the nearest hit.

#include <glm/vec3.hpp>

namespace raylab {

class Shape;

struct HitRecord {
    float t = 0.f;                          // the ray parameter of the hit
    glm::vec3 position{0.f};                // ray.at(t)
    glm::vec3 normal{0.f};                  // filled only by integrators that shade with it
    const Shape* object = nullptr;          // the object hit (a sphere, a plane), set by Scene::intersect
};

} // namespace raylab
