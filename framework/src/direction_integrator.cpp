#include "raylab/integrator.h"

namespace raylab {

Color DirectionIntegrator::Li(const Scene& /*scene*/, const Ray& ray) const { return (ray.direction + 1.f) * 0.5f; }

} // namespace raylab
