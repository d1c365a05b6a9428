// Lab 3's pictures, by the names their scene files' [render] shading gives: the student's
// RayCastIntegrator in each of its shadings.
#include "raylab/integrator_registry.h"

#include <memory>

namespace raylab {

namespace {

IntegratorFactory rayCast(Shading shading) {
    return [shading] { return std::unique_ptr<Integrator>(std::make_unique<RayCastIntegrator>(shading)); };
}

const IntegratorRegistrar kFlat("flat", rayCast(Shading::Flat));
const IntegratorRegistrar kPlaceholderNormal("placeholder_normal", rayCast(Shading::PlaceholderNormal));
const IntegratorRegistrar kCosine("cosine", rayCast(Shading::Cosine));

} // namespace

} // namespace raylab
