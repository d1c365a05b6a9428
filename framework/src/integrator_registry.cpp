#include "raylab/integrator_registry.h"

#include "src/name_registry.h"
#include "src/text.h"

#include <algorithm>
#include <stdexcept>

namespace raylab {

namespace {

// What a name draws: an integrator (rays) with its parameters, or an image at once (`image` set).
// One registry for both, since a scene file's `[render] shading` names either.
struct Drawing {
    ShadingFactory integrator;
    std::vector<ShadingParameter> parameters;
    ImageMaker image;
};

// Built on first use: registrars run during static initialisation, in any order of files.
NameRegistry<Drawing>& drawings() {
    static NameRegistry<Drawing> registry("integrator");
    return registry;
}

// Every declared parameter's value: from `values`, or its default.
ShadingParameters parameterValues(const std::string& name, const std::vector<ShadingParameter>& declared,
                                  const ShadingParameters& values) {
    for (const auto& given : values)
        if (std::none_of(declared.begin(), declared.end(), [&](const ShadingParameter& p) { return p.key == given.first; }))
            throw std::invalid_argument("shading '" + name + "' has no parameter '" + given.first + "'");
    ShadingParameters all;
    for (const ShadingParameter& p : declared) {
        const auto given = values.find(p.key);
        const float value = given != values.end() ? given->second : p.defaultValue;
        if (!(value >= p.min && value <= p.max))
            throw std::invalid_argument("shading '" + name + "': " + p.key + " = " + showNumber(value) + " is not in [" +
                                        showNumber(p.min) + ", " + showNumber(p.max) + "]");
        all.emplace(p.key, value);
    }
    return all;
}

} // namespace

void registerIntegrator(const std::string& name, IntegratorFactory factory, const char* file, unsigned line) {
    drawings().add(name, {[factory = std::move(factory)](const ShadingParameters&) { return factory(); }, {}, {}},
                   {file, line});
}

void registerIntegrator(const std::string& name, std::vector<ShadingParameter> parameters, ShadingFactory factory,
                        const char* file, unsigned line) {
    drawings().add(name, {std::move(factory), std::move(parameters), {}}, {file, line});
}

void registerImage(const std::string& name, ImageMaker maker, const char* file, unsigned line) {
    drawings().add(name, {{}, {}, std::move(maker)}, {file, line});
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

std::vector<ShadingParameter> registeredShadingParameters(const std::string& name) {
    const auto* drawing = drawings().find(name);
    return drawing != nullptr ? drawing->value.parameters : std::vector<ShadingParameter>{};
}

std::unique_ptr<Integrator> makeRegisteredIntegrator(const std::string& name, const ShadingParameters& values) {
    if (!isRegisteredIntegrator(name)) {
        std::string known;
        for (const std::string& n : registeredIntegratorNames())
            known += (known.empty() ? "" : ", ") + n;
        throw std::invalid_argument("no integrator '" + name + "' (registered: " + (known.empty() ? "none" : known) +
                                    ")");
    }
    const Drawing& drawing = drawings().find(name)->value;
    return drawing.integrator(parameterValues(name, drawing.parameters, values));
}

std::vector<std::string> registeredIntegratorNames() { return drawings().names(); }

} // namespace raylab
