#include "src/scene_file.h"

#include "raylab/integrator_registry.h"
#include "raylab/kind_registry.h"
#include "src/messages.h"
#include "src/text.h"
#include "src/toml_reader.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <optional>
#include <string_view>

namespace raylab {

namespace {

constexpr std::int64_t kMaxSamples = 1 << 20;

// Every number of a scene is stored as a float.
constexpr double kFloatMax = double(std::numeric_limits<float>::max());
// A point's coordinates: two points are then at most 2 sqrt(3) 1e18 = 3.5e18 apart, whose square
// (1.2e37) is still a float.
constexpr double kMaxCoordinate = 1e18;

// What a tool finds a figure by (SceneDescription::roles).
constexpr std::string_view kRoles[] = {"bench", "aliased", "antialiased"};

// `largest`: the largest magnitude of an item (a point's coordinates are bounded more than float's).
std::optional<glm::vec3> vec3(const TomlReader& r, const toml::table& table, std::string_view section,
                              std::string_view key, double largest = kFloatMax) {
    const toml::node* node = table.get(key);
    if (node == nullptr) return std::nullopt;
    const std::string name = std::string(section) + std::string(key);
    const toml::array* array = node->as_array();
    if (array == nullptr || array->size() != 3) r.fail(node, name, "expected an array of 3 numbers such as [0.0, 1.0, 0.0]");
    glm::vec3 v;
    for (int k = 0; k < 3; ++k) {
        const toml::node& item = *array->get(std::size_t(k));
        double value = 0.;
        if (auto f = item.as_floating_point()) value = f->get();
        else if (auto i = item.as_integer()) value = double(i->get());
        else r.fail(node, name, "item " + std::to_string(k) + " is " + TomlReader::typeName(item) + ", not a number");
        const std::string what = "item " + std::to_string(k) + " = " + showNumber(value);
        if (!std::isfinite(value)) r.fail(node, name, what + " is not finite");
        if (std::abs(value) > largest)
            r.fail(node, name,
                   what + " is too large: at most " + showNumber(largest) +
                       (largest < kFloatMax ? " (so that squared distances stay within float)" : " (float's range)"));
        v[k] = float(value);
    }
    return v;
}

void readCamera(const TomlReader& r, const toml::table& t, CameraDescription& camera) {
    r.onlyKeys(t, "[camera] ", {"position", "look_at", "up", "fovy"});
    if (auto fovy = r.number(t, "[camera] ", "fovy")) {
        if (!(*fovy > 0. && *fovy < 180.))
            r.fail(t.get("fovy"), "[camera] fovy", showNumber(*fovy) + " degrees has no meaning; it must be strictly between 0 and 180");
        camera.fovy = float(*fovy);
    }
    const auto position = vec3(r, t, "[camera] ", "position", kMaxCoordinate);
    const auto target = vec3(r, t, "[camera] ", "look_at", kMaxCoordinate);
    const auto up = vec3(r, t, "[camera] ", "up");
    if (!position && !target && !up) return; // the default frame with this fovy
    if (!position || !target)
        r.fail(&t, "[camera]", "a lookAt camera needs both position and look_at (up defaults to [0, 1, 0])");
    camera.lookAt = true;
    camera.position = *position;
    camera.target = *target;
    if (up) camera.up = *up;
}

// A table's value of `p`, checked against its declaration; nothing when it is absent and not required.
void readParameter(const TomlReader& r, const toml::table& t, const std::string& section, const KindParameter& p,
                   KindValues& values) {
    const std::string name = section + " " + p.key;
    const toml::node* node = t.get(p.key);
    if (node == nullptr) {
        if (p.required == Required::Yes) r.fail(&t, section, p.key + " is required (" + p.meaning + ")");
        return;
    }
    if (p.type == ParameterType::Number) {
        const double value = r.numberOf(*node, name);
        const std::string why = p.rangeReason.empty() ? "" : " (" + p.rangeReason + ")";
        if (value < p.min) r.fail(node, name, showNumber(value) + " is too small: at least " + showNumber(p.min) + why);
        if (value > p.max) r.fail(node, name, showNumber(value) + " is too large: at most " + showNumber(p.max) + why);
        values.set(p.key, value);
        return;
    }
    const glm::vec3 v = *vec3(r, t, section + " ", p.key, p.type == ParameterType::Point ? kMaxCoordinate : kFloatMax);
    if (p.type == ParameterType::Direction && v == glm::vec3(0.f)) r.fail(node, name, "[0, 0, 0] has no direction");
    values.set(p.key, v);
}

// [[kind]] tables, for each kind of object or light registered (raylab/kind_registry.h): each value
// as its kind declares it, then the object or light as the kind makes it.
void readKinds(const TomlReader& r, const toml::table& root, Scene& scene) {
    for (const RegisteredKind* kind : registeredKinds()) {
        const std::string section = "[[" + kind->name + "]]";
        std::vector<std::string_view> keys;
        for (const KindParameter& p : kind->parameters) keys.push_back(p.key);
        for (const toml::table* table : r.tables(root, kind->name)) {
            r.onlyKeys(*table, section + " ", keys);
            KindValues values;
            for (const KindParameter& p : kind->parameters) readParameter(r, *table, section, p, values);
            try {
                kind->add(values, scene);
            } catch (const KindParameterError& e) {
                if (e.key().empty()) r.fail(table, section, e.what());
                r.fail(table->get(e.key()), section + " " + e.key(), e.what());
            } catch (const std::invalid_argument& e) {
                r.fail(table, section, e.what());
            }
        }
    }
}

// [shading]: the parameters its shading declares (integrator_registry.h), each a finite number in
// its range, and no other key.
void readShadingParameters(const TomlReader& r, const toml::table& root, SceneDescription& d) {
    const toml::table* t = r.table(root, "", "shading");
    if (t == nullptr) return;
    const std::vector<ShadingParameter> declared = registeredShadingParameters(d.shading);
    if (declared.empty() && !t->empty())
        r.fail(&t->begin()->second, "[shading] " + std::string(t->begin()->first.str()),
               "the shading '" + d.shading + "' takes no parameters");
    std::vector<std::string_view> keys;
    for (const ShadingParameter& p : declared) keys.push_back(p.key);
    r.onlyKeys(*t, "[shading] ", keys);
    for (const ShadingParameter& p : declared) {
        const toml::node* node = t->get(p.key);
        if (node == nullptr) continue; // its default
        const std::string name = "[shading] " + p.key;
        const double value = r.numberOf(*node, name);
        if (!(value >= p.min && value <= p.max))
            r.fail(node, name, showNumber(value) + " is not in [" + showNumber(p.min) + ", " + showNumber(p.max) + "]");
        d.shadingParameters[p.key] = float(value);
    }
}

// [render.adaptive]: only with sampler = "adaptive", whose first pass needs two samples to compare
// and whose second pass must take more samples than the first.
void readAdaptive(const TomlReader& r, const toml::table& render, SceneDescription& d) {
    const toml::table* t = r.table(render, "[render] ", "adaptive");
    if (d.sampler != SamplerKind::Adaptive) {
        if (t != nullptr)
            r.fail(render.get("adaptive"), "[render.adaptive]",
                   "only has a meaning with sampler = \"adaptive\" (the sampler is \"" + std::string(samplerName(d.sampler)) + "\")");
        return;
    }
    if (d.samples < 2)
        r.fail(render.get("samples") != nullptr ? render.get("samples") : &render, "[render] samples",
               "adaptive sampling needs at least 2 samples per pixel to see them disagree (got " + std::to_string(d.samples) + ")");
    if (t == nullptr) return;
    const std::string_view section = "[render.adaptive] ";
    r.onlyKeys(*t, section, {"threshold", "max_samples", "widen", "sampler"});
    if (auto threshold = r.number(*t, section, "threshold")) {
        if (*threshold < 0.) r.fail(t->get("threshold"), "[render.adaptive] threshold", std::to_string(*threshold) + " must be >= 0");
        if (*threshold > kFloatMax)
            r.fail(t->get("threshold"), "[render.adaptive] threshold",
                   showNumber(*threshold) + " is beyond float's range (" + showNumber(kFloatMax) + ")");
        d.adaptive.threshold = float(*threshold);
    }
    d.adaptive.maxSamples = int(r.integer(*t, section, "max_samples", 1, kMaxSamples).value_or(d.adaptive.maxSamples));
    if (d.adaptive.maxSamples <= d.samples)
        r.fail(t->get("max_samples") != nullptr ? t->get("max_samples") : t, "[render.adaptive] max_samples",
               std::to_string(d.adaptive.maxSamples) + " must be more than samples = " + std::to_string(d.samples) +
                   ", or no pixel gets more samples");
    d.adaptive.widen = r.boolean(*t, section, "widen").value_or(d.adaptive.widen);
    if (auto sampler = r.string(*t, section, "sampler")) {
        auto kind = samplerKindFromString(*sampler);
        if (!kind || *kind == SamplerKind::Adaptive || *kind == SamplerKind::Center)
            r.fail(t->get("sampler"), "[render.adaptive] sampler",
                   "'" + *sampler + "' is not one of random, stratified, grid, sobol, r2");
        d.adaptive.within = *kind;
    }
}

// [figure] roles = ["bench", ...]: each a role of kRoles, once.
std::vector<std::string> readRoles(const TomlReader& r, const toml::table& figure) {
    const toml::node* node = figure.get("roles");
    if (node == nullptr) return {};
    const toml::array* list = node->as_array();
    std::string known;
    for (std::string_view k : kRoles) known += (known.empty() ? "" : ", ") + std::string(k);
    if (list == nullptr) r.fail(node, "[figure] roles", "expected a list of roles (" + known + ")");
    std::vector<std::string> roles;
    for (const toml::node& item : *list) {
        const std::optional<std::string> role = item.value_exact<std::string>();
        if (!role || std::find(std::begin(kRoles), std::end(kRoles), *role) == std::end(kRoles))
            r.fail(&item, "[figure] roles", "each role is one of " + known);
        if (std::find(roles.begin(), roles.end(), *role) != roles.end()) r.fail(&item, "[figure] roles", *role + " is there twice");
        roles.push_back(*role);
    }
    return roles;
}

SceneDescription readSceneFile(const std::filesystem::path& file) {
    const toml::table root = parseTomlFile(file);
    const TomlReader r(file);
    std::vector<std::string_view> tables = {"figure", "image", "camera", "render", "shading", "background"};
    for (const RegisteredKind* kind : registeredKinds()) tables.push_back(kind->name);
    r.onlyKeys(root, "", tables);

    SceneDescription d;
    d.file = file;
    d.id = file.stem().string();
    if (const toml::table* t = r.table(root, "", "figure")) {
        r.onlyKeys(*t, "[figure] ", {"title", "roles"}); // its lab is the one whose lab.toml lists it
        d.title = r.string(*t, "[figure] ", "title").value_or("");
        d.roles = readRoles(r, *t);
    }
    if (const toml::table* t = r.table(root, "", "image")) {
        r.onlyKeys(*t, "[image] ", {"width", "height"});
        d.width = int(r.integer(*t, "[image] ", "width", 1, 16384).value_or(d.width));
        d.height = int(r.integer(*t, "[image] ", "height", 1, 16384).value_or(d.height));
    }
    if (const toml::table* t = r.table(root, "", "camera")) readCamera(r, *t, d.camera);
    if (const toml::table* t = r.table(root, "", "render")) {
        r.onlyKeys(*t, "[render] ", {"shading", "samples", "sampler", "seed", "adaptive"});
        if (auto shading = r.string(*t, "[render] ", "shading")) {
            if (!isRegisteredIntegrator(*shading) && !isRegisteredImage(*shading)) { // registered by the labs
                std::string known;
                for (const std::string& name : registeredIntegratorNames()) known += (known.empty() ? "" : ", ") + name;
                r.fail(t->get("shading"), "[render] shading", "'" + *shading + "' is not one of " + known);
            }
            d.shading = *shading;
        }
        d.samples = int(r.integer(*t, "[render] ", "samples", 1, kMaxSamples).value_or(1));
        if (auto sampler = r.string(*t, "[render] ", "sampler")) {
            auto kind = samplerKindFromString(*sampler);
            if (!kind)
                r.fail(t->get("sampler"), "[render] sampler", "'" + *sampler + "' is not one of " + std::string(samplerNames()));
            d.sampler = *kind;
        } else if (d.samples > 1) {
            d.sampler = SamplerKind::Random;
        }
        readAdaptive(r, *t, d);
        d.seed = std::uint64_t(r.integer(*t, "[render] ", "seed", 0, INT64_MAX).value_or(0));
    }
    readShadingParameters(r, root, d);
    if (auto background = vec3(r, root, "", "background")) d.scene.background = *background;
    readKinds(r, root, d.scene);
    return d;
}

} // namespace

std::string sceneTablesReference() {
    constexpr std::string_view kTypes[] = {"number", "point [x, y, z]", "direction [x, y, z], not zero", "colour [r, g, b]"};
    std::string text = "# The objects and lights of a scene file: a [[table]] for each, the table's name a kind the\n"
                       "# framework or a lab of the course registers (raylab/kind_registry.h).\n";
    for (const KindRole role : {KindRole::Object, KindRole::Light}) {
        text += role == KindRole::Object ? "\n# Objects\n" : "\n# Lights\n";
        for (const RegisteredKind* kind : registeredKinds()) {
            if (kind->role != role) continue;
            text += "\n[[" + kind->name + "]] # " + kind->meaning + "\n";
            for (const KindParameter& p : kind->parameters) {
                std::string line = p.key + ": " + std::string(kTypes[int(p.type)]);
                if (p.type == ParameterType::Number && (p.min > -kFloatMax || p.max < kFloatMax))
                    line += " in [" + showNumber(p.min) + ", " + showNumber(p.max) + "]";
                line += p.required == Required::Yes ? ", required" : (p.type == ParameterType::Color ? ", default white" : ", optional");
                text += "#   " + line + ": " + p.meaning + "\n";
            }
        }
    }
    return text;
}

SceneDescription loadSceneFile(const std::filesystem::path& file) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(file, error)) throw SceneError(tr("figures.no_scene_file", {{"file", file.string()}}));
    try {
        return readSceneFile(file);
    } catch (const TomlError& e) {
        throw SceneError(e.what());
    }
}

const SceneDescription& sceneWithRole(const std::vector<SceneDescription>& scenes, std::string_view role,
                                      const std::filesystem::path& folder) {
    const SceneDescription* found = nullptr;
    for (const SceneDescription& d : scenes)
        if (std::find(d.roles.begin(), d.roles.end(), role) != d.roles.end()) {
            if (found != nullptr)
                throw SceneError(d.file.string() + ": [figure] roles: " + std::string(role) + " is also the role of " +
                                 found->file.string());
            found = &d;
        }
    if (found == nullptr)
        throw SceneError(folder.string() + ": no scene file has [figure] roles = [\"" + std::string(role) + "\"]");
    return *found;
}

std::vector<SceneDescription> loadSceneFolder(const std::filesystem::path& folder) {
    std::error_code error;
    if (!std::filesystem::is_directory(folder, error)) throw SceneError(tr("figures.no_scene_folder", {{"folder", folder.string()}}));
    std::vector<SceneDescription> scenes;
    for (const auto& entry : std::filesystem::directory_iterator(folder))
        if (entry.path().extension() == ".toml") scenes.push_back(loadSceneFile(entry.path()));
    std::sort(scenes.begin(), scenes.end(), [](const auto& a, const auto& b) { return a.id < b.id; });
    return scenes;
}

} // namespace raylab
