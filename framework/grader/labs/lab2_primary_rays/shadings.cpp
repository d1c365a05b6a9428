// Lab 2's picture, by the name its scene file's [render] shading gives: each ray's direction.
#include "raylab/integrator_registry.h"

namespace raylab {

RAYLAB_REGISTER_INTEGRATOR("directions", DirectionIntegrator);

} // namespace raylab
