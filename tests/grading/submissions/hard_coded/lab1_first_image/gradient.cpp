// Hostile: the answers of the handout's sizes learnt by heart (5 x 3, 7 x 4, 1 x 3, 4 x 1, and
// the figure's 600 x 400), nothing for any other size.
#include "raylab/gradient.h"

namespace raylab {

void fillGradient(Texture& texture) {
    const int w = texture.width(), h = texture.height();
    const bool known = (w == 5 && h == 3) || (w == 7 && h == 4) || (w == 1 && h == 3) || (w == 4 && h == 1) ||
                       (w == 600 && h == 400);
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i)
            texture.setPixel(i, j, known ? Color(w > 1 ? float(i) / float(w - 1) : 0.f, h > 1 ? float(j) / float(h - 1) : 0.f, 0.f)
                                         : Color(0.f));
}

} // namespace raylab
