#pragma once
// Integrators by name. A lab adds its own from its own file, and a scene file's `[render] shading`
// names it: a new lab draws its figures with no change to the framework.
//
//   RAYLAB_REGISTER_INTEGRATOR("toy_normals", ToyNormalIntegrator);  // at namespace scope, in the lab's file

#include "raylab/integrator.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace raylab {

using IntegratorFactory = std::function<std::unique_ptr<Integrator>()>;

// Adds `name`; a name registered twice throws std::logic_error (two labs would draw one shading).
void registerIntegrator(const std::string& name, IntegratorFactory factory);

bool isRegisteredIntegrator(const std::string& name);

// A new integrator of that name; throws std::invalid_argument naming the registered ones if none.
std::unique_ptr<Integrator> makeRegisteredIntegrator(const std::string& name);

// The registered names, sorted.
std::vector<std::string> registeredIntegratorNames();

// Registers at static initialisation: the macro below declares one.
struct IntegratorRegistrar {
    IntegratorRegistrar(const std::string& name, IntegratorFactory factory) {
        registerIntegrator(name, std::move(factory));
    }
};

} // namespace raylab

#define RAYLAB_INTEGRATOR_CONCAT_(a, b) a##b
#define RAYLAB_INTEGRATOR_CONCAT(a, b) RAYLAB_INTEGRATOR_CONCAT_(a, b)
#define RAYLAB_REGISTER_INTEGRATOR(name, Type)                                                                         \
    static const ::raylab::IntegratorRegistrar RAYLAB_INTEGRATOR_CONCAT(raylabIntegratorRegistrar, __LINE__)(          \
        (name), [] { return std::unique_ptr<::raylab::Integrator>(std::make_unique<Type>()); })
