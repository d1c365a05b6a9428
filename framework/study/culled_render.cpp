#include "culled_render.h"

#include "src/figure.h"
#include "src/parallel.h"
#include "raylab/renderer.h"
#include "raylab/sampler.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace raylab::study {

namespace {

constexpr int kTileSize = 16;

struct Tile {
    int x0, y0, x1, y1;
};

glm::dvec3 unit(const glm::vec3& v) { return glm::normalize(glm::dvec3(v)); }

// atan2 of the cross and dot products: accurate for tiny angles too, where acos is not.
double angleBetween(const glm::dvec3& a, const glm::dvec3& b) {
    return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

// The spheres a ray through the tile can meet. A ray of the tile starts at the eye, inside the cone
// of the tile's four corner rays (the directions through a rectangle of the screen: the largest
// angle to the cone's axis is a corner's); a sphere is kept when its own cone from the eye comes
// within that angle of the axis. The margin covers the float rays' rounding (about 1e-7) many times
// over and is far below a pixel (about 1e-2 radians here).
std::vector<SphereGeometry> spheresSeenBy(const Scene& scene, const PerspectiveCamera& camera, const Tile& t) {
    const float w = float(camera.width()), h = float(camera.height());
    const Ray corners[4] = {camera.generateRay(float(t.x0) / w, float(t.y0) / h), camera.generateRay(float(t.x1) / w, float(t.y0) / h),
                            camera.generateRay(float(t.x0) / w, float(t.y1) / h), camera.generateRay(float(t.x1) / w, float(t.y1) / h)};
    for (const Ray& r : corners)
        if (r.origin != corners[0].origin) return scene.all<SphereGeometry>(); // not a pinhole: no cone to cull with
    glm::dvec3 axis(0.);
    for (const Ray& r : corners) axis += unit(r.direction);
    axis = glm::normalize(axis);
    double spread = 0.;
    for (const Ray& r : corners) spread = std::max(spread, angleBetween(axis, unit(r.direction)));

    const glm::dvec3 eye(corners[0].origin);
    std::vector<SphereGeometry> seen;
    for (const SphereGeometry& sphere : scene.all<SphereGeometry>()) {
        const glm::dvec3 toCentre = glm::dvec3(sphere.center()) - eye;
        const double distance = glm::length(toCentre), radius = sphere.radius();
        if (distance <= radius * 1.001) { // the eye in the sphere, or at its surface
            seen.push_back(sphere);
            continue;
        }
        const double reach = spread + std::asin(radius / distance);
        if (angleBetween(axis, toCentre / distance) <= reach * (1. + 1e-3) + 1e-6) seen.push_back(sphere);
    }
    return seen;
}

} // namespace

Texture renderCulled(const SceneDescription& d, int threads) {
    if (d.sampler == SamplerKind::Adaptive || (d.sampler == SamplerKind::Center && d.samples == 1))
        throw std::invalid_argument(d.file.string() + ": a culled render samples each pixel through lab 5 "
                                                      "(not adaptively, not one centred sample)");
    const SceneRender whole(d); // the render space, the camera and the integrator
    const PerspectiveCamera& camera = whole.camera();
    std::vector<Tile> tiles;
    for (int y = 0; y < d.height; y += kTileSize)
        for (int x = 0; x < d.width; x += kTileSize)
            tiles.push_back({x, y, std::min(x + kTileSize, d.width), std::min(y + kTileSize, d.height)});

    Texture image(d.width, d.height);
    parallelFor(tiles.size(), threads, false, [&](std::size_t k, unsigned) {
        const Tile& t = tiles[k];
        Scene near = whole.scene(); // its other kinds of objects are all kept
        near.setAll(spheresSeenBy(whole.scene(), camera, t));
        Renderer renderer(near, camera, whole.integrator());
        if (d.samples != 1) renderer.setNbPixelSamples(d.samples);
        // Each pixel's samples as Renderer::renderImage draws them: the pixel and the scene's seed.
        for (int j = t.y0; j < t.y1; ++j)
            for (int i = t.x0; i < t.x1; ++i) {
                PixelSampler sampler(d.sampler, d.samples, d.seed, i, j, d.width);
                image.setPixel(i, j, renderer.renderPixel(i, j, sampler));
            }
    });
    return image;
}

} // namespace raylab::study
