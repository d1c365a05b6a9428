// Lab @N@ (a toy): each primary ray coloured by its direction, inverted.
#include "toy_colour.h"

namespace raylab {

Color toyColour(const Ray& ray) {
    return Color(1.f) - (ray.direction + 1.f) * 0.5f;
}

} // namespace raylab
