// Lab 1: your first image. This file is yours to edit.
#include "gradient.h"
#include "raylab/todo.h"

namespace raylab {

// Fill every pixel (i, j) of the texture (i: column from the left, j: row from the top) with
//   red = i / (W - 1), green = j / (H - 1), blue = 0,
// where W = texture.width() and H = texture.height(). An image 1 pixel wide has no W - 1 to divide
// by: use red = 0 there (and green = 0 when it is 1 pixel high).
// Write a pixel with texture.setPixel(i, j, Color(red, green, blue)).
void fillGradient(Texture& texture) {
    RAYLAB_TODO("lab 1", "fillGradient");
}

} // namespace raylab
