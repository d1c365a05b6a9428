#include "raylab/integrator_registry.h"

#include "src/name_registry.h"

#include <stdexcept>

namespace raylab {

namespace {

// What a name draws: an integrator (rays), or an image at once (`image` set). One registry for both,
// since a scene file's `[render] shading` names either.
struct Drawing {
    IntegratorFactory integrator;
    ImageMaker image;
};

// Built on first use: registrars run during static initialisation, in any order of files.
NameRegistry<Drawing>& drawings() {
    static NameRegistry<Drawing> registry("integrator");
    return registry;
}

} // namespace

void registerIntegrator(const std::string& name, IntegratorFactory factory, const char* file, unsigned line) {
    drawings().add(name, {std::move(factory), {}}, {file, line});
}

void registerImage(const std::string& name, ImageMaker maker, const char* file, unsigned line) {
    drawings().add(name, {{}, std::move(maker)}, {file, line});
}

bool isRegisteredImage(const std::string& name) {
    const auto* drawing = drawings().find(name);
    return drawing != nullptr && drawing->value.image;
}

Texture makeRegisteredImage(const std::string& name, int width, int height) {
    if (!isRegisteredImage(name)) throw std::invalid_argument("no image '" + name + "'");
    return drawings().find(name)->value.image(width, height);
}

bool isRegisteredIntegrator(const std::string& name) {
    const auto* drawing = drawings().find(name);
    return drawing != nullptr && drawing->value.integrator;
}

std::unique_ptr<Integrator> makeRegisteredIntegrator(const std::string& name) {
    if (!isRegisteredIntegrator(name)) {
        std::string known;
        for (const std::string& n : registeredIntegratorNames())
            known += (known.empty() ? "" : ", ") + n;
        throw std::invalid_argument("no integrator '" + name + "' (registered: " + (known.empty() ? "none" : known) +
                                    ")");
    }
    return drawings().find(name)->value.integrator();
}

std::vector<std::string> registeredIntegratorNames() { return drawings().names(); }

} // namespace raylab
