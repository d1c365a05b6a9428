#include "raylab/integrator_registry.h"

#include <map>
#include <stdexcept>

namespace raylab {

namespace {

// Built on first use: registrars run during static initialisation, in any order of files.
std::map<std::string, IntegratorFactory>& registry() {
    static std::map<std::string, IntegratorFactory> factories;
    return factories;
}

} // namespace

void registerIntegrator(const std::string& name, IntegratorFactory factory) {
    if (!registry().emplace(name, std::move(factory)).second)
        throw std::logic_error("the integrator '" + name + "' is registered twice");
}

bool isRegisteredIntegrator(const std::string& name) {
    return registry().count(name) != 0;
}

std::unique_ptr<Integrator> makeRegisteredIntegrator(const std::string& name) {
    const auto it = registry().find(name);
    if (it == registry().end()) {
        std::string known;
        for (const std::string& n : registeredIntegratorNames())
            known += (known.empty() ? "" : ", ") + n;
        throw std::invalid_argument("no integrator '" + name + "' (registered: " + (known.empty() ? "none" : known) +
                                    ")");
    }
    return it->second();
}

std::vector<std::string> registeredIntegratorNames() {
    std::vector<std::string> names;
    for (const auto& entry : registry())
        names.push_back(entry.first);
    return names;
}

} // namespace raylab
