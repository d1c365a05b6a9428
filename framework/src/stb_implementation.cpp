// stb_image and stb_image_write, compiled here on every system (Debian's libstb is used only for
// its headers): stb_image_write then deflates its PNGs with zlib at a low level, several times
// faster than stb's own deflate for files a little larger (docs/performance.md).
#include <zlib.h>

#include <climits>
#include <cstdlib>

namespace {

// stb_image_write's compression hook: `data` deflated into a zlib stream that stb frees with free().
// stb's `quality` (its own deflate's effort) does not apply to zlib's levels and is ignored.
unsigned char* deflateWithZlib(unsigned char* data, int length, int* outLength, int /*quality*/) {
    uLongf size = compressBound(uLong(length));
    auto* out = static_cast<unsigned char*>(std::malloc(size));
    if (out == nullptr) return nullptr;
    if (compress2(out, &size, data, uLong(length), Z_BEST_SPEED) != Z_OK || size > uLongf(INT_MAX)) {
        std::free(out);
        return nullptr;
    }
    *outLength = int(size);
    return out;
}

} // namespace

#define STBIW_ZLIB_COMPRESS deflateWithZlib
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image.h>
#include <stb_image_write.h>
