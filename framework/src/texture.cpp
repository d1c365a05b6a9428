#include "raylab/texture.h"

#include <stdexcept>
#include <string>

namespace raylab {

Texture::Texture(int width, int height) : m_width(width), m_height(height) {
    if (width < 1 || height < 1)
        throw std::invalid_argument("Texture: size " + std::to_string(width) + " x " + std::to_string(height) +
                                    " has no pixel; width and height must be at least 1");
    m_pixels.assign(std::size_t(width) * std::size_t(height), Color(0.f));
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
