// Lab @N@ (a toy): each primary ray coloured by its direction, inverted.
#include "toy_colour.h"
#include "raylab/todo.h"

namespace raylab {

Color toyColour(const Ray& ray) {
    RAYLAB_TODO("lab @N@", "toyColour");
}

} // namespace raylab
