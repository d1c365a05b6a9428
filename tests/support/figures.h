#pragma once
// Helpers for tests that render the course's figures.

#include "src/figure.h"
#include "support/scene_files.h"
#include "raylab/image_io.h"

#include <doctest/doctest.h>

#include <string>

namespace raylab::test {

inline SceneDescription figureScene(const std::string& id) {
    return loadSceneFile(figureSceneFile(id));
}

// Renders a figure and fails the test unless it rendered.
inline Image8 renderFigure(const SceneDescription& d, int threads = 0) {
    const FigureResult r = renderScene(d, RenderOptions{threads, false});
    REQUIRE_MESSAGE(r.status == FigureResult::Status::Rendered, d.id << ": " << r.message);
    std::uint64_t nonFinite = 0;
    Image8 image = quantize(*r.image, &nonFinite);
    CHECK(nonFinite == 0);
    return image;
}

inline Image8 renderFigure(const std::string& id, int threads = 0) { return renderFigure(figureScene(id), threads); }

inline bool pixelIs(const Image8& image, int i, int j, int r, int g, int b) {
    const std::uint8_t* p = image.pixel(i, j);
    return p[0] == r && p[1] == g && p[2] == b;
}

// The pixels that are not the background colour, and their centroid in pixel coordinates.
struct Coverage {
    int count = 0;
    double x = 0., y = 0.;
};

inline Coverage coverageOf(const Image8& image, int bgR, int bgG, int bgB) {
    Coverage c;
    for (int j = 0; j < image.height; ++j)
        for (int i = 0; i < image.width; ++i)
            if (!pixelIs(image, i, j, bgR, bgG, bgB)) {
                ++c.count;
                c.x += i + 0.5;
                c.y += j + 0.5;
            }
    if (c.count > 0) {
        c.x /= c.count;
        c.y /= c.count;
    }
    return c;
}

} // namespace raylab::test
