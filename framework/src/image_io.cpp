#include "raylab/image_io.h"

#include "src/atomic_file.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

namespace raylab {

std::uint8_t toByte(float v) {
    const float clamped = v < 0.f ? 0.f : (v > 1.f ? 1.f : v);
    return std::uint8_t(std::lround(clamped * 255.f));
}

Image8 quantize(const Texture& texture, std::uint64_t* nonFinite) {
    Image8 image{texture.width(), texture.height(), {}};
    image.rgb.resize(std::size_t(image.width) * std::size_t(image.height) * 3);
    std::uint64_t bad = 0;
    std::size_t k = 0;
    for (const Color& c : texture.pixels()) {
        const bool finite = std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b);
        bad += finite ? 0 : 1;
        for (int channel = 0; channel < 3; ++channel)
            image.rgb[k++] = finite ? toByte(c[channel]) : kNonFiniteRgb[channel];
    }
    if (nonFinite != nullptr) *nonFinite = bad;
    return image;
}

namespace {

// The bytes of an 8-bit PNG file of the image.
std::string encodePng(const Image8& image) {
    std::string bytes;
    const auto append = [](void* context, void* data, int size) {
        static_cast<std::string*>(context)->append(static_cast<const char*>(data), std::size_t(size));
    };
    if (stbi_write_png_to_func(append, &bytes, image.width, image.height, 3, image.rgb.data(), image.width * 3) == 0)
        throw std::runtime_error("cannot encode a " + std::to_string(image.width) + " x " + std::to_string(image.height) +
                                 " image as PNG");
    return bytes;
}

} // namespace

void writePng(const std::filesystem::path& path, const Image8& image) { writeFileAtomically(path, encodePng(image)); }

Image8 readImage(const std::filesystem::path& path) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error))
        throw std::runtime_error(path.string() + ": no such file");
    int width = 0, height = 0, channels = 0;
    std::unique_ptr<stbi_uc, void (*)(void*)> data(stbi_load(path.string().c_str(), &width, &height, &channels, 3),
                                                   stbi_image_free);
    if (!data) throw std::runtime_error(path.string() + ": not a readable image (" + stbi_failure_reason() + ")");
    Image8 image{width, height, {}};
    image.rgb.assign(data.get(), data.get() + std::size_t(width) * std::size_t(height) * 3);
    return image;
}

} // namespace raylab
