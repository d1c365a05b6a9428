#pragma once
// Integrators by name. A lab adds its own from its own file, and a scene file's `[render] shading`
// names it: a new lab draws its figures with no change to the framework. A picture drawn without
// rays (lab 1's gradient) registers the whole image instead, under a name of the same kind.
//
//   RAYLAB_REGISTER_INTEGRATOR("toy_normals", ToyNormalIntegrator);  // at namespace scope, in the lab's file
//
// A shading may declare parameters, numbers its scene file sets in its [shading] table; the file
// may set no other key:
//
//   const IntegratorRegistrar kLambert("lambert", {{"ambient", 0.f, 0.f, 1.f}},
//       [](const ShadingParameters& p) { return std::make_unique<LambertIntegrator>(p.at("ambient")); });

#include "raylab/integrator.h"
#include "raylab/texture.h"

#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace raylab {

using IntegratorFactory = std::function<std::unique_ptr<Integrator>()>;

// A number a shading reads from its scene file's [shading] table: its key, its value when the file
// does not set it, and the values it accepts (min <= value <= max).
struct ShadingParameter {
    std::string key;
    float defaultValue = 0.f;
    float min = -std::numeric_limits<float>::max();
    float max = std::numeric_limits<float>::max();
};

// The values of a shading's parameters by key: every one it declares, set or by default.
using ShadingParameters = std::map<std::string, float, std::less<>>;

using ShadingFactory = std::function<std::unique_ptr<Integrator>(const ShadingParameters&)>;

// Adds `name`, registered at file:line; a name registered twice throws std::logic_error naming both
// places (two labs would draw one shading).
void registerIntegrator(const std::string& name, IntegratorFactory factory, const char* file = __builtin_FILE(),
                        unsigned line = __builtin_LINE());
// The same for a shading with parameters: `factory` receives the value of each.
void registerIntegrator(const std::string& name, std::vector<ShadingParameter> parameters, ShadingFactory factory,
                        const char* file = __builtin_FILE(), unsigned line = __builtin_LINE());

bool isRegisteredIntegrator(const std::string& name);

// The parameters the integrator or image `name` declares (none for most); empty for an unknown name.
std::vector<ShadingParameter> registeredShadingParameters(const std::string& name);

// A new integrator of that name, with `values` for some of its parameters and the others' defaults.
// Throws std::invalid_argument naming the registered ones when there is none, or naming the key of
// a value it does not declare or does not accept.
std::unique_ptr<Integrator> makeRegisteredIntegrator(const std::string& name, const ShadingParameters& values = {});

// The registered names (integrators and images), sorted.
std::vector<std::string> registeredIntegratorNames();

// A picture with no rays: the W x H image at once.
using ImageMaker = std::function<Texture(int width, int height)>;

// Adds `name`; a name registered twice, as an image or an integrator, throws std::logic_error.
void registerImage(const std::string& name, ImageMaker maker, const char* file = __builtin_FILE(),
                   unsigned line = __builtin_LINE());

bool isRegisteredImage(const std::string& name);

// The image of that name, W x H; throws std::invalid_argument when there is none.
Texture makeRegisteredImage(const std::string& name, int width, int height);

// Registers at static initialisation, with the line that declares it: the macro below declares one.
struct IntegratorRegistrar {
    IntegratorRegistrar(const std::string& name, IntegratorFactory factory, const char* file = __builtin_FILE(),
                        unsigned line = __builtin_LINE()) {
        registerIntegrator(name, std::move(factory), file, line);
    }
    IntegratorRegistrar(const std::string& name, std::vector<ShadingParameter> parameters, ShadingFactory factory,
                        const char* file = __builtin_FILE(), unsigned line = __builtin_LINE()) {
        registerIntegrator(name, std::move(parameters), std::move(factory), file, line);
    }
};

struct ImageRegistrar {
    ImageRegistrar(const std::string& name, ImageMaker maker, const char* file = __builtin_FILE(),
                   unsigned line = __builtin_LINE()) {
        registerImage(name, std::move(maker), file, line);
    }
};

} // namespace raylab

#define RAYLAB_INTEGRATOR_CONCAT_(a, b) a##b
#define RAYLAB_INTEGRATOR_CONCAT(a, b) RAYLAB_INTEGRATOR_CONCAT_(a, b)
#define RAYLAB_REGISTER_INTEGRATOR(name, Type)                                                                         \
    static const ::raylab::IntegratorRegistrar RAYLAB_INTEGRATOR_CONCAT(raylabIntegratorRegistrar, __LINE__)(          \
        (name), [] { return std::unique_ptr<::raylab::Integrator>(std::make_unique<Type>()); })
