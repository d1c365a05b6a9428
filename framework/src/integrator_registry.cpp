#include "raylab/integrator_registry.h"

#include <algorithm>
#include <map>
#include <stdexcept>

namespace raylab {

namespace {

// Built on first use: registrars run during static initialisation, in any order of files.
std::map<std::string, IntegratorFactory>& registry() {
    static std::map<std::string, IntegratorFactory> factories;
    return factories;
}

std::map<std::string, ImageMaker>& images() {
    static std::map<std::string, ImageMaker> makers;
    return makers;
}

void refuseTaken(const std::string& name) {
    if (registry().count(name) != 0 || images().count(name) != 0)
        throw std::logic_error("the integrator '" + name + "' is registered twice");
}

} // namespace

void registerIntegrator(const std::string& name, IntegratorFactory factory) {
    refuseTaken(name);
    registry().emplace(name, std::move(factory));
}

void registerImage(const std::string& name, ImageMaker maker) {
    refuseTaken(name);
    images().emplace(name, std::move(maker));
}

bool isRegisteredImage(const std::string& name) { return images().count(name) != 0; }

Texture makeRegisteredImage(const std::string& name, int width, int height) {
    const auto it = images().find(name);
    if (it == images().end()) throw std::invalid_argument("no image '" + name + "'");
    return it->second(width, height);
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
    for (const auto& entry : images())
        names.push_back(entry.first);
    std::sort(names.begin(), names.end());
    return names;
}

} // namespace raylab
