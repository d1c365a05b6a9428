#pragma once
// From linear float colours to 8-bit PNG files and back.

#include "raylab/texture.h"

#include <cstdint>
#include <filesystem>
#include <vector>

namespace raylab {

// An 8-bit RGB image, row-major, 3 bytes a pixel.
struct Image8 {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgb;

    const std::uint8_t* pixel(int i, int j) const { return &rgb[3 * (std::size_t(j) * width + i)]; }
};

// Clamps v to [0, 1] and rounds 255 v to the nearest integer. NaN is not a colour: see quantize.
std::uint8_t toByte(float v);

// The colour written for a pixel with a NaN or an infinite channel: loud magenta, never silent.
inline constexpr std::uint8_t kNonFiniteRgb[3] = {255, 0, 255};

// Quantizes every pixel; counts (in *nonFinite, when given) the pixels written as kNonFiniteRgb.
Image8 quantize(const Texture& texture, std::uint64_t* nonFinite = nullptr);

// Writes an 8-bit PNG whole or not at all (atomic_file.h); throws WriteError naming the path and
// the reason when it cannot.
void writePng(const std::filesystem::path& path, const Image8& image);

// Reads a PNG (or any format stb_image reads) as 8-bit RGB; throws std::runtime_error naming the
// path and the reason when the file is missing, unreadable or not an image.
Image8 readImage(const std::filesystem::path& path);

} // namespace raylab
