#include "raylab/texture.h"

#include <stdexcept>
#include <string>
#include <utility>

namespace raylab {

namespace {

// width x height; throws when that has no pixel.
std::size_t pixelCount(int width, int height) {
    if (width < 1 || height < 1)
        throw std::invalid_argument("Texture: size " + std::to_string(width) + " x " + std::to_string(height) +
                                    " has no pixel; width and height must be at least 1");
    return std::size_t(width) * std::size_t(height);
}

} // namespace

Texture::Texture(int width, int height)
    : Texture(width, height, std::vector<Color>(pixelCount(width, height), Color(0.f))) {}

Texture::Texture(int width, int height, std::vector<Color> pixels)
    : m_width(width), m_height(height), m_pixels(std::move(pixels)) {
    if (m_pixels.size() != pixelCount(width, height))
        throw std::invalid_argument("Texture: " + std::to_string(m_pixels.size()) + " pixels for a " + std::to_string(width) +
                                    " x " + std::to_string(height) + " image; it needs width x height");
}

void Texture::checkInside(int i, int j) const {
    if (i < 0 || i >= m_width || j < 0 || j >= m_height) throwOutside(i, j);
}

void Texture::throwOutside(int i, int j) const {
    throw std::out_of_range("Texture: pixel (i=" + std::to_string(i) + ", j=" + std::to_string(j) +
                                ") is outside the " + std::to_string(m_width) + " x " + std::to_string(m_height) +
                                " image (i is the column, j the row)");
}

Color Texture::getPixel(int i, int j) const {
    checkInside(i, j);
    return m_pixels[std::size_t(j) * std::size_t(m_width) + std::size_t(i)];
}

} // namespace raylab
