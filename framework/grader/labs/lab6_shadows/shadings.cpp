// Lab 6's pictures, by the names their scene files' [render] shading gives: the student's
// PointLightIntegrator with the shadow test and without it, the ambient term from [shading].
#include "raylab/integrator_registry.h"
#include "point_light_integrator.h"

#include <memory>

namespace raylab {

namespace {

ShadingFactory pointLight(bool shadows) {
    return [shadows](const ShadingParameters& p) {
        return std::unique_ptr<Integrator>(std::make_unique<PointLightIntegrator>(p.at("ambient"), shadows));
    };
}

// The fraction of its colour a surface shows where no light reaches it.
const ShadingParameter kAmbient{"ambient", 0.f, 0.f, 1.f};

const IntegratorRegistrar kPointLight("point_light", {kAmbient}, pointLight(true));
const IntegratorRegistrar kPointLightNoShadows("point_light_no_shadows", {kAmbient}, pointLight(false));

} // namespace

} // namespace raylab
