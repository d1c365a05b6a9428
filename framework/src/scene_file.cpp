#include "src/scene_file.h"

#include "raylab/integrator_registry.h"
#include "src/messages.h"
#include "src/text.h"

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <stdexcept>
#include <optional>
#include <string_view>

namespace raylab {

namespace {

constexpr std::int64_t kMaxSamples = 1 << 20;

// Every number of a scene is stored as a float.
constexpr double kFloatMax = double(std::numeric_limits<float>::max());
// The intersection squares the radius and the distance from the ray's origin to the centre in
// float (docs/numerics.md, section 2): both squares must stay normal floats.
const double kMinRadius = std::sqrt(double(std::numeric_limits<float>::min())); // 1.08e-19
const double kMaxRadius = std::sqrt(kFloatMax);                                 // 1.84e19
// A point's coordinates: two points are then at most 2 sqrt(3) 1e18 = 3.5e18 apart, whose square
// (1.2e37) is still a float.
constexpr double kMaxCoordinate = 1e18;

// What a tool finds a figure by (SceneDescription::roles).
constexpr std::string_view kRoles[] = {"bench", "aliased", "antialiased"};

// Reads one file, naming the file, the line and the key in every error.
class Reader {
public:
    explicit Reader(std::filesystem::path file) : m_file(std::move(file)) {}

    [[noreturn]] void fail(const toml::node* node, std::string_view where, const std::string& problem) const {
        const int line = node != nullptr ? int(node->source().begin.line) : 0;
        std::string message = m_file.string();
        if (line > 0) message += ":" + std::to_string(line);
        throw SceneError(message + ": " + std::string(where) + ": " + problem);
    }

    void onlyKeys(const toml::table& table, std::string_view section, std::initializer_list<std::string_view> allowed) const {
        for (auto&& [key, node] : table) {
            if (std::find(allowed.begin(), allowed.end(), key.str()) == allowed.end()) {
                std::string known;
                for (std::string_view k : allowed) known += (known.empty() ? "" : ", ") + std::string(k);
                fail(&node, std::string(section) + std::string(key.str()), "unknown key (known keys: " + known + ")");
            }
        }
    }

    std::optional<double> number(const toml::table& table, std::string_view section, std::string_view key) const {
        const toml::node* node = table.get(key);
        if (node == nullptr) return std::nullopt;
        std::optional<double> value;
        if (auto f = node->as_floating_point()) value = f->get();
        else if (auto i = node->as_integer()) value = double(i->get());
        else fail(node, name(section, key), "expected a number, got " + typeName(*node));
        if (!std::isfinite(*value)) fail(node, name(section, key), "must be finite, got " + showNumber(*value));
        return value;
    }

    std::optional<std::int64_t> integer(const toml::table& table, std::string_view section, std::string_view key,
                                        std::int64_t lo, std::int64_t hi) const {
        const toml::node* node = table.get(key);
        if (node == nullptr) return std::nullopt;
        auto i = node->as_integer();
        if (!i) fail(node, name(section, key), "expected an integer, got " + typeName(*node));
        if (i->get() < lo || i->get() > hi)
            fail(node, name(section, key),
                 std::to_string(i->get()) + " is out of range [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
        return i->get();
    }

    std::optional<std::string> string(const toml::table& table, std::string_view section, std::string_view key) const {
        const toml::node* node = table.get(key);
        if (node == nullptr) return std::nullopt;
        auto s = node->as_string();
        if (!s) fail(node, name(section, key), "expected a string, got " + typeName(*node));
        return s->get();
    }

    // `largest`: the largest magnitude of an item (a point's coordinates are bounded more than float's).
    std::optional<glm::vec3> vec3(const toml::table& table, std::string_view section, std::string_view key,
                                  double largest = kFloatMax) const {
        const toml::node* node = table.get(key);
        if (node == nullptr) return std::nullopt;
        auto array = node->as_array();
        if (!array || array->size() != 3)
            fail(node, name(section, key), "expected an array of 3 numbers such as [0.0, 1.0, 0.0]");
        glm::vec3 v;
        for (int k = 0; k < 3; ++k) {
            const toml::node& item = *array->get(std::size_t(k));
            double value = 0.;
            if (auto f = item.as_floating_point()) value = f->get();
            else if (auto i = item.as_integer()) value = double(i->get());
            else fail(node, name(section, key), "item " + std::to_string(k) + " is " + typeName(item) + ", not a number");
            const std::string what = "item " + std::to_string(k) + " = " + showNumber(value);
            if (!std::isfinite(value)) fail(node, name(section, key), what + " is not finite");
            if (std::abs(value) > largest)
                fail(node, name(section, key),
                     what + " is too large: at most " + showNumber(largest) +
                         (largest < kFloatMax ? " (so that squared distances stay within float)" : " (float's range)"));
            v[k] = float(value);
        }
        return v;
    }

    const toml::table* table(const toml::table& parent, std::string_view key) const {
        const toml::node* node = parent.get(key);
        if (node == nullptr) return nullptr;
        if (!node->is_table()) fail(node, key, "expected a table [" + std::string(key) + "]");
        return node->as_table();
    }

    static std::string name(std::string_view section, std::string_view key) {
        return std::string(section) + std::string(key);
    }

    static std::string typeName(const toml::node& node) {
        switch (node.type()) {
        case toml::node_type::string: return "a string";
        case toml::node_type::integer: return "an integer";
        case toml::node_type::floating_point: return "a number";
        case toml::node_type::boolean: return "a boolean";
        case toml::node_type::array: return "an array";
        case toml::node_type::table: return "a table";
        default: return "a date or time";
        }
    }

private:
    std::filesystem::path m_file;
};

void readCamera(const Reader& r, const toml::table& t, CameraDescription& camera) {
    r.onlyKeys(t, "[camera] ", {"position", "look_at", "up", "fovy"});
    if (auto fovy = r.number(t, "[camera] ", "fovy")) {
        if (!(*fovy > 0. && *fovy < 180.))
            r.fail(t.get("fovy"), "[camera] fovy", showNumber(*fovy) + " degrees has no meaning; it must be strictly between 0 and 180");
        camera.fovy = float(*fovy);
    }
    const auto position = r.vec3(t, "[camera] ", "position", kMaxCoordinate);
    const auto target = r.vec3(t, "[camera] ", "look_at", kMaxCoordinate);
    const auto up = r.vec3(t, "[camera] ", "up");
    if (!position && !target && !up) return; // the default frame with this fovy
    if (!position || !target)
        r.fail(&t, "[camera]", "a lookAt camera needs both position and look_at (up defaults to [0, 1, 0])");
    camera.lookAt = true;
    camera.position = *position;
    camera.target = *target;
    if (up) camera.up = *up;
}

void readSpheres(const Reader& r, const toml::node& node, Scene& scene) {
    const toml::array* spheres = node.as_array();
    if (spheres == nullptr || !spheres->is_array_of_tables())
        r.fail(&node, "[[sphere]]", "expected [[sphere]] tables");
    for (const toml::node& item : *spheres) {
        const toml::table& t = *item.as_table();
        r.onlyKeys(t, "[[sphere]] ", {"center", "radius", "color"});
        const auto center = r.vec3(t, "[[sphere]] ", "center", kMaxCoordinate);
        const auto radius = r.number(t, "[[sphere]] ", "radius");
        if (!center || !radius) r.fail(&t, "[[sphere]]", "a sphere needs a center and a radius");
        if (!(*radius > 0.)) r.fail(t.get("radius"), "[[sphere]] radius", showNumber(*radius) + " must be positive");
        if (*radius < kMinRadius)
            r.fail(t.get("radius"), "[[sphere]] radius",
                   showNumber(*radius) + " is too small: its square underflows float (the smallest radius is " +
                       showNumber(kMinRadius) + ")");
        if (*radius > kMaxRadius)
            r.fail(t.get("radius"), "[[sphere]] radius",
                   showNumber(*radius) + " is too large: its square overflows float (the largest radius is " +
                       showNumber(kMaxRadius) + ")");
        const Color color = r.vec3(t, "[[sphere]] ", "color").value_or(Color(1.f));
        try { // the float radius at the edge of the range
            scene.spheres.emplace_back(*center, float(*radius), color);
        } catch (const std::invalid_argument& e) {
            r.fail(t.get("radius"), "[[sphere]] radius", std::string(e.what()).substr(std::string_view("sphere: ").size()));
        }
    }
}

// [render.adaptive]: only with sampler = "adaptive", whose first pass needs two samples to compare
// and whose second pass must take more samples than the first.
void readAdaptive(const Reader& r, const toml::table& render, SceneDescription& d) {
    const toml::table* t = r.table(render, "adaptive");
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
    if (const toml::node* widen = t->get("widen")) {
        if (!widen->is_boolean()) r.fail(widen, "[render.adaptive] widen", "expected true or false, got " + Reader::typeName(*widen));
        d.adaptive.widen = widen->as_boolean()->get();
    }
    if (auto sampler = r.string(*t, section, "sampler")) {
        auto kind = samplerKindFromString(*sampler);
        if (!kind || *kind == SamplerKind::Adaptive || *kind == SamplerKind::Center)
            r.fail(t->get("sampler"), "[render.adaptive] sampler",
                   "'" + *sampler + "' is not one of random, stratified, grid, sobol, r2");
        d.adaptive.within = *kind;
    }
}

} // namespace


namespace {

// [figure] roles = ["bench", ...]: each a role of kRoles, once.
std::vector<std::string> readRoles(const Reader& r, const toml::table& figure) {
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

} // namespace

SceneDescription loadSceneFile(const std::filesystem::path& file) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(file, error)) throw SceneError(tr("figures.no_scene_file", {{"file", file.string()}}));
    toml::table root;
    try {
        root = toml::parse_file(file.string());
    } catch (const toml::parse_error& e) {
        throw SceneError(file.string() + ":" + std::to_string(e.source().begin.line) + ": not valid TOML: " +
                         std::string(e.description()));
    }
    const Reader r(file);
    r.onlyKeys(root, "", {"figure", "image", "camera", "render", "background", "sphere"});

    SceneDescription d;
    d.file = file;
    d.id = file.stem().string();
    d.scene.spheres.clear();
    if (const toml::table* t = r.table(root, "figure")) {
        r.onlyKeys(*t, "[figure] ", {"title", "roles"}); // its lab is the one whose lab.toml lists it
        d.title = r.string(*t, "[figure] ", "title").value_or("");
        d.roles = readRoles(r, *t);
    }
    if (const toml::table* t = r.table(root, "image")) {
        r.onlyKeys(*t, "[image] ", {"width", "height"});
        d.width = int(r.integer(*t, "[image] ", "width", 1, 16384).value_or(d.width));
        d.height = int(r.integer(*t, "[image] ", "height", 1, 16384).value_or(d.height));
    }
    if (const toml::table* t = r.table(root, "camera")) readCamera(r, *t, d.camera);
    if (const toml::table* t = r.table(root, "render")) {
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
    if (auto background = r.vec3(root, "", "background")) d.scene.background = *background;
    if (const toml::node* spheres = root.get("sphere")) readSpheres(r, *spheres, d.scene);
    return d;
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
