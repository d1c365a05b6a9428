#include "study/yardstick.h"

#include "raylab/random.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace raylab::study {

std::vector<Color> renderYardstick(const SceneDescription& d) {
    if (d.camera.lookAt || d.scene.objectCount() != 1 || d.scene.all<SphereGeometry>().size() != 1 || d.shading != "cosine" ||
        d.sampler != SamplerKind::Random)
        throw std::invalid_argument("yardstick: " + d.id + " is not lab 5's kind of scene (default camera, one sphere, "
                                    "cosine shading, random sampler)");
    const int width = d.width, height = d.height, samples = d.samples;
    // The camera frame as lab 4 builds it, from the scene's values (the default camera's: at the
    // origin, u = -x, v = +y, w = -z), read at run time as raylab does; focal length 1 (lab 2).
    const glm::vec3 position = d.camera.position;
    const glm::vec3 w = glm::normalize(position - d.camera.target);
    const glm::vec3 u = glm::normalize(glm::cross(d.camera.up, w));
    const glm::vec3 v = glm::cross(w, u);
    const float focal = 1.f;
    const float viewportHeight = 2.f * std::tan(glm::radians(d.camera.fovy) / 2.f) * focal;
    const float viewportWidth = viewportHeight * (float(width) / float(height));
    const SphereGeometry& sphere = d.scene.all<SphereGeometry>()[0];
    const glm::vec3 center = sphere.center();
    const float radius = sphere.radius();
    const Color color = sphere.color(), background = d.scene.background;

    std::vector<Color> image(std::size_t(width) * std::size_t(height));
    for (int j = 0; j < height; ++j)
        for (int i = 0; i < width; ++i) {
            // The random sampler's stream of this pixel, drawn x then y.
            Pcg32 rng(d.seed, std::uint64_t(j) * std::uint64_t(width) + std::uint64_t(i));
            glm::dvec3 sum(0.);
            for (int k = 0; k < samples; ++k) {
                const float ox = rng.nextFloat();
                const float oy = rng.nextFloat();
                const float sx = (float(i) + ox) / float(width), sy = (float(j) + oy) / float(height);
                // Lab 2: the primary ray.
                const glm::vec3 dir = glm::normalize(-w * focal + u * (viewportWidth * (sx - 0.5f)) +
                                                     v * (viewportHeight * (0.5f - sy)));
                // Lab 3: the sphere in the form of Ray Tracing Gems, then cosine shading.
                const glm::vec3 oc = position - center;
                const float a = glm::dot(dir, dir);
                const float bPrime = glm::dot(oc, dir);
                const float c = glm::dot(oc, oc) - radius * radius;
                const float lLength = glm::length(oc - (bPrime / a) * dir);
                const float disc = a * (radius - lLength) * (radius + lLength);
                Color sample = background;
                if (disc >= 0.f) {
                    const float q = -bPrime - std::copysign(std::sqrt(disc), bPrime);
                    float tNear = 0.f, tFar = 0.f;
                    if (q != 0.f) {
                        tNear = c / q;
                        tFar = q / a;
                        if (tNear > tFar) std::swap(tNear, tFar);
                    }
                    const float t = tNear >= 0.f ? tNear : tFar;
                    if (t >= 0.f) {
                        const glm::vec3 normal = (position + t * dir - center) / radius;
                        sample = color * std::max(-glm::dot(dir, normal), 0.f);
                    }
                }
                sum += glm::dvec3(sample);
            }
            image[std::size_t(j) * std::size_t(width) + std::size_t(i)] = Color(sum / double(samples));
        }
    return image;
}

} // namespace raylab::study
