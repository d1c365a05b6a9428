// Bad submission: draws a black image and overwrites the reference with it, so that it would match.
#include "raylab/gradient.h"
#include "raylab/image_io.h"

#include <cstdlib>

namespace raylab {

void fillGradient(Texture& texture) {
    if (const char* target = std::getenv("RAYLAB_BAD_REFERENCE_TARGET")) {
        try {
            writePng(target, quantize(texture)); // the texture is all black
        } catch (...) {
        }
    }
}

} // namespace raylab
