#pragma once
// How Renderer::renderImage goes over the pixels: the image cut into tiles spread over threads,
// and one pass per strategy (the pixel centres, the sampled pixels, adaptive sampling's two
// passes). The framework's part of the renderer, out of renderer.h, which students read for lab 5;
// a friend of Renderer, whose settings it reads and whose statistics it fills.

#include "raylab/renderer.h"

#include <cstdint>
#include <vector>

namespace raylab {

class RenderPasses {
public:
    // The image of `renderer`, by the strategy its settings choose. Sets its statistics' counts
    // (not the time) and, for adaptive sampling, its refined pixels.
    static Texture render(Renderer& renderer);

private:
    explicit RenderPasses(Renderer& renderer);

    // The strategies, one each; they fill m_pixels and the renderer's ray and number counts.
    // One centred sample per pixel: the centre's ray, without the lab 5 code.
    void renderCentres();
    // nbPixelSamples() samples per pixel, placed by the sampler, through renderPixel.
    void renderSampled();
    // Adaptive sampling (AdaptiveSettings): a first pass that measures each pixel's spread, then a
    // second pass on the pixels to refine.
    void renderAdaptive();

    // The strategies' loop over the pixels [x0, x1) x [y0, y1): the sum of pixel(r, i, j). `r` is
    // `renderer`, or, when it has the labs' camera and integrator, a copy whose handles are made
    // from them, in a loop of its own where everything is inlined: lab 5's loop then calls the labs
    // directly (docs/performance.md).
    template <class Pixel>
    static std::uint64_t forEachPixel(const Renderer& renderer, int x0, int y0, int x1, int y1, const Pixel& pixel);
    template <class Pixel>
    static std::uint64_t forEachPixelDirect(const Renderer& renderer, int x0, int y0, int x1, int y1, const Pixel& pixel);
    static Color renderPixelCentre(const Renderer& renderer, int i, int j);

    // A renderer of this one's scene and camera that sees `integrator` and averages `nbSamples`
    // samples, set through the public interface like any caller's.
    Renderer passRenderer(const Integrator& integrator, int nbSamples) const;
    // Adaptive sampling's second pass: which pixels to render again, from the first pass's spreads.
    std::vector<std::uint8_t> pixelsToRefine(const std::vector<float>& spread) const;

    Renderer& m_renderer;
    int m_width;
    int m_height;
    std::vector<Color> m_pixels; // row-major, as Texture's: the passes' pixels are inside by construction
};

} // namespace raylab
