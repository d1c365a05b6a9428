#pragma once
// A width x height image of linear RGB floats. Pixel (i, j) is column i from the left, row j from the top.

#include <glm/vec3.hpp>

#include <cstddef>
#include <vector>

namespace raylab {

using Color = glm::vec3;

class Texture {
public:
    // A black image. Throws std::invalid_argument when width or height is below 1.
    Texture(int width, int height);
    // The image of these pixels, row-major (pixel (i, j) at j * width + i). Throws
    // std::invalid_argument when their number is not width x height.
    Texture(int width, int height, std::vector<Color> pixels);

    int width() const { return m_width; }
    int height() const { return m_height; }

    // Throws std::out_of_range naming (i, j) and the size when the pixel is outside the image.
    void setPixel(int i, int j, const Color& color) {
        if (i < 0 || i >= m_width || j < 0 || j >= m_height) throwOutside(i, j);
        m_pixels[std::size_t(j) * std::size_t(m_width) + std::size_t(i)] = color;
    }
    Color getPixel(int i, int j) const;

    const std::vector<Color>& pixels() const { return m_pixels; }

private:
    void checkInside(int i, int j) const;
    [[noreturn]] void throwOutside(int i, int j) const;

    int m_width;
    int m_height;
    std::vector<Color> m_pixels; // row-major: index j * width + i
};

} // namespace raylab
