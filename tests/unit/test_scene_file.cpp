#include "raylab/integrator_registry.h"
#include "raylab/kind_registry.h"
#include "support/scene_files.h"
#include "grader/lab_catalog.h"
#include "src/messages.h"
#include "src/scene_file.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <fstream>
#include <random>
#include <set>
#include <string>
#include <vector>

using namespace raylab;

namespace {

// Writes a scene file in the temporary folder and loads it.
SceneDescription loadText(const std::string& text, const std::string& name = "scene.toml") {
    // One folder per test process: test runs from several build trees must not share files.
    static const auto folder = std::filesystem::temp_directory_path() /
                               ("raylab_scene_tests_" + std::to_string(std::random_device{}()));
    const auto file = folder / name;
    std::filesystem::create_directories(file.parent_path());
    std::ofstream(file) << text;
    return loadSceneFile(file);
}

std::string errorOf(const std::string& text) {
    try {
        loadText(text);
    } catch (const SceneError& e) {
        const std::string message = e.what();
        return message.substr(message.find("scene.toml"));
    }
    return "no error";
}

// The shadings the course's labs register: those their figures use, and "lambert", the framework's
// reference with lights (framework/study/instructors/lambert_shading.cpp), in alphabetical order.
std::vector<std::string> courseShadings() {
    std::set<std::string> names{"lambert"};
    for (const SceneDescription& d : grader::loadFiguresInLabOrder({}, grader::loadLabCatalog(test::kLabsDir)))
        names.insert(d.shading);
    return {names.begin(), names.end()};
}

// The scene files of the course's labs (a lab the course leaves out may name a shading no program of
// this course registers).
std::vector<std::filesystem::path> courseSceneFiles() {
    std::vector<std::filesystem::path> files;
    for (const grader::LabDescription& lab : grader::loadLabCatalog(test::kLabsDir).labs)
        for (const grader::LabFigure& figure : lab.figures) files.push_back(figure.scene);
    return files;
}

} // namespace

TEST_SUITE("scene files") {

TEST_CASE("every figure scene of the course's labs loads, and no two have one id") {
    // Which figures there are is the labs' to say (their lab.toml, checked by the lab catalogue).
    std::vector<std::string> ids;
    for (const std::filesystem::path& file : courseSceneFiles()) {
        CAPTURE(file);
        const SceneDescription d = loadSceneFile(file);
        CHECK(d.id == file.stem().string());
        CHECK(std::find(ids.begin(), ids.end(), d.id) == ids.end());
        ids.push_back(d.id);
    }
    CHECK_FALSE(ids.empty());
}

TEST_CASE("a full scene file") {
    const SceneDescription d = loadText(R"(
background = [0.1, 0.2, 0.3]
[figure]
title = "t"
[image]
width = 64
height = 32
[camera]
position = [1, 2, 3]
look_at = [0, 0, 0]
fovy = 45
[render]
shading = "flat"
samples = 4
sampler = "stratified"
seed = 9
[[sphere]]
center = [0, 0, 1]
radius = 0.5
color = [1, 0, 0]
[[sphere]]
center = [0, 0, 5]
radius = 2
)");
    CHECK(d.id == "scene");
    CHECK(d.width == 64);
    CHECK(d.height == 32);
    CHECK(d.camera.lookAt);
    CHECK(d.camera.position == glm::vec3(1.f, 2.f, 3.f));
    CHECK(d.camera.up == glm::vec3(0.f, 1.f, 0.f));
    CHECK(d.camera.fovy == 45.f);
    CHECK(d.shading == "flat");
    CHECK(d.samples == 4);
    CHECK(d.sampler == SamplerKind::Stratified);
    CHECK(d.seed == 9);
    CHECK(d.scene.background == Color(0.1f, 0.2f, 0.3f));
    REQUIRE(d.scene.all<SphereGeometry>().size() == 2);
    CHECK(d.scene.all<SphereGeometry>()[1].radius() == 2.f);
    CHECK(d.scene.all<SphereGeometry>()[1].color() == Color(1.f));
}

TEST_CASE("an empty file is the default camera on an empty scene") {
    const SceneDescription d = loadText("");
    CHECK_FALSE(d.camera.lookAt);
    CHECK(d.scene.all<SphereGeometry>().empty());
    CHECK(d.samples == 1);
    CHECK(d.sampler == SamplerKind::Center);
}

TEST_CASE("errors name the file, the line and the key") {
    CHECK(errorOf("[camera]\nfovy = 60\nzoom = 2\n") ==
          "scene.toml:3: [camera] zoom: unknown key (known keys: position, look_at, up, fovy)");
    // A figure's lab is the lab.toml that lists it, never the scene file.
    CHECK(errorOf("[figure]\nlab = 4\n") == "scene.toml:2: [figure] lab: unknown key (known keys: title, roles)");
    CHECK(errorOf("[image]\nwidth = \"600\"\n") == "scene.toml:2: [image] width: expected an integer, got a string");
    CHECK(errorOf("[image]\nwidth = 0\n") == "scene.toml:2: [image] width: 0 is out of range [1, 16384]");
    CHECK(errorOf("[camera]\nfovy = 180\n") ==
          "scene.toml:2: [camera] fovy: 180 degrees has no meaning; it must be strictly between 0 and 180");
    CHECK(errorOf("[camera]\nfovy = nan\n") == "scene.toml:2: [camera] fovy: must be finite, got nan");
    CHECK(errorOf("[[sphere]]\ncenter = [0, 0]\nradius = 1\n") ==
          "scene.toml:2: [[sphere]] center: expected an array of 3 numbers such as [0.0, 1.0, 0.0]");
    CHECK(errorOf("[[sphere]]\ncenter = [0, 0, 1]\n") == "scene.toml:1: [[sphere]]: radius is required (its radius)");
    CHECK(errorOf("[[sphere]]\ncenter = [0, 0, 1]\nradius = -1\n") == "scene.toml:3: [[sphere]] radius: -1 is too small: at least 1.08420217e-19 (its square must stay a normal float)");
    std::string shadings;
    for (const std::string& name : courseShadings()) shadings += (shadings.empty() ? "" : ", ") + name;
    CHECK(errorOf("[render]\nshading = \"phong\"\n") == "scene.toml:2: [render] shading: 'phong' is not one of " + shadings);
    CHECK(errorOf("[render]\nsampler = \"magic\"\n") ==
          "scene.toml:2: [render] sampler: 'magic' is not one of center, random, stratified, grid, sobol, r2, adaptive");
    CHECK(errorOf("[camera]\nlook_at = [0, 0, 1]\n") ==
          "scene.toml:1: [camera]: a lookAt camera needs both position and look_at (up defaults to [0, 1, 0])");
    CHECK(errorOf("[image\nwidth = 3\n").rfind("scene.toml:1:7: not valid TOML: ", 0) == 0);
    // The known keys end with each registered kind's table, of object or light (the course's labs may add theirs).
    std::string kinds;
    for (const RegisteredKind* kind : registeredKinds()) kinds += ", " + kind->name;
    CHECK(kinds.find(", plane") != std::string::npos);
    CHECK(kinds.find(", sphere") != std::string::npos);
    CHECK(kinds.find(", light") != std::string::npos);
    CHECK(errorOf("colour = 3\n") ==
          "scene.toml:1: colour: unknown key (known keys: figure, image, camera, render, shading, background" + kinds + ")");
    // In French, with its no-break space before the colon after the key as before the known keys.
    const raylab::Language before = raylab::language();
    raylab::setLanguage(raylab::Language::Fr);
    CHECK(errorOf("[camera]\nfovy = 60\nzoom = 2\n") ==
          "scene.toml:3: [camera] zoom\u00A0: clé inconnue (clés connues\u00A0: position, look_at, up, fovy)");
    raylab::setLanguage(before);
}

TEST_CASE("every number is checked against the bounds the float numerics justify, naming the file, line and key") {
    const std::string sphere = "[[sphere]]\ncenter = [0, 0, 3]\nradius = ";
    CHECK(errorOf(sphere + "1e-50\n") == "scene.toml:3: [[sphere]] radius: 1e-50 is too small: at least 1.08420217e-19 "
                                           "(its square must stay a normal float)");
    CHECK(errorOf(sphere + "1e39\n") == "scene.toml:3: [[sphere]] radius: 1e+39 is too large: at most 1.84467435e+19 "
                                          "(its square must stay a normal float)");
    CHECK(errorOf(sphere + "1e20\n") == "scene.toml:3: [[sphere]] radius: 1e+20 is too large: at most 1.84467435e+19 "
                                          "(its square must stay a normal float)");
    CHECK(errorOf("[[sphere]]\ncenter = [1e39, 0, 3]\nradius = 1\n") ==
          "scene.toml:2: [[sphere]] center: item 0 = 1e+39 is too large: at most 1e+18 (so that squared distances stay "
          "within float)");
    CHECK(errorOf("[camera]\nposition = [0, -2e18, 0]\nlook_at = [0, 0, 1]\n") ==
          "scene.toml:2: [camera] position: item 1 = -2e+18 is too large: at most 1e+18 (so that squared distances "
          "stay within float)");
    CHECK(errorOf("background = [1e39, 0, 0]\n") ==
          "scene.toml:1: background: item 0 = 1e+39 is too large: at most 3.40282347e+38 (float's range)");
    CHECK(errorOf("[camera]\nfovy = 1e39\n") ==
          "scene.toml:2: [camera] fovy: 1e+39 degrees has no meaning; it must be strictly between 0 and 180");
    CHECK(errorOf("[render]\nsamples = 4\nsampler = \"adaptive\"\n[render.adaptive]\nthreshold = 1e300\n") ==
          "scene.toml:5: [render.adaptive] threshold: 1e+300 is beyond float's range (3.40282347e+38)");
    // The radii of docs/numerics.md, and the edges of the range, are accepted.
    for (const char* radius : {"1e-3", "1e3", "2e-19", "1.8e19"}) {
        CAPTURE(radius);
        CHECK(loadText(sphere + radius + "\n").scene.all<SphereGeometry>().size() == 1);
    }
}

TEST_CASE("a figure's roles name it for the tools, not its id: one scene a role") {
    std::vector<SceneDescription> scenes;
    for (const std::filesystem::path& file : courseSceneFiles()) scenes.push_back(loadSceneFile(file));
    for (const char* role : {"bench", "aliased", "antialiased"}) {
        CAPTURE(role);
        const auto count = std::count_if(scenes.begin(), scenes.end(), [&](const SceneDescription& d) {
            return std::find(d.roles.begin(), d.roles.end(), role) != d.roles.end();
        });
        CHECK(count <= 1); // a course without the lab that has the role has none
    }
    CHECK(loadText("[figure]\nroles = [\"aliased\", \"bench\"]\n").roles == std::vector<std::string>{"aliased", "bench"});
    CHECK(errorOf("[figure]\nroles = [\"speed\"]\n") ==
          "scene.toml:2: [figure] roles: each role is one of bench, aliased, antialiased");
    CHECK(errorOf("[figure]\nroles = [\"bench\", \"bench\"]\n") == "scene.toml:2: [figure] roles: bench is there twice");
    std::vector<SceneDescription> two = {loadText("[figure]\nroles = [\"bench\"]\n", "a.toml"),
                                         loadText("[figure]\nroles = [\"bench\"]\n", "b.toml")};
    CHECK_THROWS_WITH_AS(sceneWithRole(two, "bench", "folder"), doctest::Contains("b.toml: [figure] roles: bench is also the role of"),
                         SceneError);
    CHECK_THROWS_WITH_AS(sceneWithRole(two, "aliased", "folder"),
                         "folder: no scene file has [figure] roles = [\"aliased\"]", SceneError);
}

TEST_CASE("every shading is a name a lab registers: one path for the figures") {
    // Each lab registers its figures' from framework/grader/labs/<lab>/shadings.cpp.
    CHECK(registeredIntegratorNames() == courseShadings());
    CHECK(isRegisteredImage("gradient")); // drawn without rays
    CHECK_FALSE(isRegisteredImage("cosine"));
    CHECK(isRegisteredIntegrator("cosine"));
    const Texture gradient = makeRegisteredImage("gradient", 3, 2); // lab 1's fillGradient (the reference here)
    CHECK(gradient.width() == 3);
    CHECK(gradient.getPixel(2, 1) == Color(1.f, 1.f, 0.f));
    CHECK_THROWS_AS(registerImage("cosine", [](int w, int h) { return Texture(w, h); }), std::logic_error);
    CHECK_THROWS_AS(registerIntegrator("gradient", [] { return std::unique_ptr<Integrator>(); }), std::logic_error);
    CHECK(loadText("[render]\nshading = \"gradient\"\n").shading == "gradient");
    CHECK(loadText("").shading == "cosine");
}

TEST_CASE("point lights and planes beside the spheres") {
    const SceneDescription d = loadText(R"(
[[sphere]]
center = [0, 0, 3]
radius = 1
[[plane]]
point = [0, -1, 0]
normal = [0, 2, 0]
color = [0.5, 0.25, 1]
[[plane]]
normal = [0, 0, -4]
offset = -10
[[light]]
position = [1, 2, 3]
intensity = 20
color = [1, 0.5, 0]
[[light]]
position = [0, 5, 0]
intensity = 2.5
)");
    CHECK(d.scene.all<SphereGeometry>().size() == 1);
    REQUIRE(d.scene.all<Plane>().size() == 2);
    CHECK(d.scene.all<Plane>()[0].point() == glm::vec3(0.f, -1.f, 0.f));
    CHECK(d.scene.all<Plane>()[0].normal() == glm::vec3(0.f, 1.f, 0.f)); // normalized
    CHECK(d.scene.all<Plane>()[0].color() == Color(0.5f, 0.25f, 1.f));
    // normal + offset: the plane dot(n, x) = offset of the unit normal n = (0, 0, -1), so z = 10.
    CHECK(d.scene.all<Plane>()[1].point() == glm::vec3(0.f, 0.f, 10.f));
    CHECK(d.scene.all<Plane>()[1].normal() == glm::vec3(0.f, 0.f, -1.f));
    CHECK(d.scene.all<Plane>()[1].color() == Color(1.f)); // white by default
    REQUIRE(d.scene.lights.size() == 2);
    CHECK(d.scene.lights[0].position == glm::vec3(1.f, 2.f, 3.f));
    CHECK(d.scene.lights[0].intensity == Color(20.f, 10.f, 0.f)); // intensity * color
    CHECK(d.scene.lights[1].intensity == Color(2.5f));
    CHECK(loadText("").scene.lights.empty());
    CHECK(loadText("").scene.all<Plane>().empty());
}

TEST_CASE("lights and planes: errors name the file, the line and the key") {
    CHECK(errorOf("[[light]]\nposition = [0, 0, 0]\n") == "scene.toml:1: [[light]]: intensity is required (its radiant intensity)");
    CHECK(errorOf("[[light]]\nposition = [0, 0, 0]\nintensity = -1\n") ==
          "scene.toml:3: [[light]] intensity: -1 is too small: at least 0 (an intensity is not negative, and fits a float)");
    CHECK(errorOf("[[light]]\nposition = [0, 0, 0]\nintensity = nan\n") ==
          "scene.toml:3: [[light]] intensity: must be finite, got nan");
    CHECK(errorOf("[[light]]\nposition = [0, 0, 0]\nintensity = 1\ncolor = [1, -1, 0]\n") ==
          "scene.toml:4: [[light]] color: (1, -1, 0): a light's colour has no negative channel");
    CHECK(errorOf("[[light]]\nposition = [0, 0, 0]\nintensity = 1e38\ncolor = [10, 1, 1]\n")
              .rfind("scene.toml:4: [[light]] color: intensity * color overflows float", 0) == 0);
    CHECK(errorOf("[[light]]\nposition = [0, 0, 0]\nintensity = 1\nradius = 2\n") ==
          "scene.toml:4: [[light]] radius: unknown key (known keys: position, intensity, color)");
    CHECK(errorOf("[[plane]]\nnormal = [0, 1, 0]\n") ==
          "scene.toml:1: [[plane]]: a plane needs a normal, and either a point or an offset");
    CHECK(errorOf("[[plane]]\nnormal = [0, 1, 0]\npoint = [0, 0, 0]\noffset = 1\n") ==
          "scene.toml:1: [[plane]]: a plane needs a normal, and either a point or an offset");
    CHECK(errorOf("[[plane]]\npoint = [0, 0, 0]\n") == "scene.toml:1: [[plane]]: normal is required (its normal, normalized when read)");
    CHECK(errorOf("[[plane]]\nnormal = [0, 0, 0]\noffset = 1\n") == "scene.toml:2: [[plane]] normal: [0, 0, 0] has no direction");
    CHECK(errorOf("[[plane]]\nnormal = [0, nan, 0]\noffset = 1\n") ==
          "scene.toml:2: [[plane]] normal: item 1 = nan is not finite");
    CHECK(errorOf("[[plane]]\nnormal = [0, 1, 0]\noffset = 1e19\n") ==
          "scene.toml:3: [[plane]] offset: 1e+19 is too large: at most 1e+18 (so that squared distances stay within float)");
    CHECK(errorOf("[[plane]]\nnormal = [0, 1, 0]\noffset = \"1\"\n") ==
          "scene.toml:3: [[plane]] offset: expected a number, got a string");
    CHECK(errorOf("[[plane]]\nnormal = [0, 1, 0]\noffset = 1\nside = 2\n") ==
          "scene.toml:4: [[plane]] side: unknown key (known keys: normal, point, offset, color)");
}

TEST_CASE("a shading reads the parameters it declares from [shading], and no other key") {
    const SceneDescription d = loadText("[render]\nshading = \"lambert\"\n[shading]\nambient = 0.1\n");
    CHECK(d.shadingParameters == ShadingParameters{{"ambient", 0.1f}});
    CHECK(loadText("[render]\nshading = \"lambert\"\n").shadingParameters.empty()); // its default, 0
    CHECK(loadText("[render]\nshading = \"lambert\"\n[shading]\nambient = 1\n").shadingParameters.at("ambient") == 1.f);
    CHECK(registeredShadingParameters("lambert").size() == 1);
    CHECK(registeredShadingParameters("cosine").empty());

    const std::string lambert = "[render]\nshading = \"lambert\"\n[shading]\n";
    CHECK(errorOf(lambert + "ambiant = 0.1\n") == "scene.toml:4: [shading] ambiant: unknown key (known keys: ambient)");
    CHECK(errorOf(lambert + "ambient = \"0.1\"\n") == "scene.toml:4: [shading] ambient: expected a number, got a string");
    CHECK(errorOf(lambert + "ambient = nan\n") == "scene.toml:4: [shading] ambient: must be finite, got nan");
    CHECK(errorOf(lambert + "ambient = 1.5\n") == "scene.toml:4: [shading] ambient: 1.5 is not in [0, 1]");
    CHECK(errorOf("[shading]\nambient = 0.1\n") == "scene.toml:2: [shading] ambient: the shading 'cosine' takes no parameters");
    CHECK(errorOf("shading = 3\n").rfind("scene.toml:1: shading: expected a table", 0) == 0);

    // Through the registry: the defaults fill in, and a value it does not declare or accept is refused.
    CHECK_NOTHROW(makeRegisteredIntegrator("lambert"));
    CHECK_THROWS_WITH_AS(makeRegisteredIntegrator("lambert", {{"ambiant", 0.1f}}), "shading 'lambert' has no parameter 'ambiant'",
                         std::invalid_argument);
    CHECK_THROWS_WITH_AS(makeRegisteredIntegrator("lambert", {{"ambient", -1.f}}),
                         "shading 'lambert': ambient = -1 is not in [0, 1]", std::invalid_argument);
    CHECK_THROWS_AS(makeRegisteredIntegrator("cosine", {{"ambient", 0.1f}}), std::invalid_argument);
}

TEST_CASE("a missing file or folder is named") {
    CHECK_THROWS_WITH_AS(loadSceneFile("no/such.toml"), "no/such.toml: no such scene file", SceneError);
    CHECK_THROWS_WITH_AS(loadSceneFolder("no/such/dir"), "no/such/dir: no such scene folder", SceneError);
}

}

TEST_SUITE("scene files") {

TEST_CASE("the adaptive sampler's keys") {
    const SceneDescription d = loadText(R"(
[render]
samples = 16
sampler = "adaptive"
[render.adaptive]
threshold = 0.1
max_samples = 64
widen = false
sampler = "sobol"
)");
    CHECK(d.sampler == SamplerKind::Adaptive);
    CHECK(d.samples == 16);
    CHECK(d.adaptive.threshold == 0.1f);
    CHECK(d.adaptive.maxSamples == 64);
    CHECK_FALSE(d.adaptive.widen);
    CHECK(d.adaptive.within == SamplerKind::Sobol);
    const SceneDescription defaults = loadText("[render]\nsamples = 4\nsampler = \"adaptive\"\n");
    CHECK(defaults.adaptive.maxSamples == 256);
    CHECK(defaults.adaptive.widen);
    CHECK(defaults.adaptive.within == SamplerKind::Stratified);
    for (const char* name : {"grid", "sobol", "r2"})
        CHECK(loadText(std::string("[render]\nsamples = 4\nsampler = \"") + name + "\"\n").sampler ==
              samplerKindFromString(name));
}

TEST_CASE("the adaptive sampler's errors name the file, the line and the key") {
    CHECK(errorOf("[render]\nsampler = \"random\"\nsamples = 4\n[render.adaptive]\nthreshold = 0.1\n") ==
          "scene.toml:4: [render.adaptive]: only has a meaning with sampler = \"adaptive\" (the sampler is \"random\")");
    CHECK(errorOf("[render]\nsampler = \"adaptive\"\nsamples = 1\n") ==
          "scene.toml:3: [render] samples: adaptive sampling needs at least 2 samples per pixel to see them disagree (got 1)");
    CHECK(errorOf("[render]\nsampler = \"adaptive\"\nsamples = 16\n[render.adaptive]\nmax_samples = 16\n") ==
          "scene.toml:5: [render.adaptive] max_samples: 16 must be more than samples = 16, or no pixel gets more samples");
    CHECK(errorOf("[render]\nsampler = \"adaptive\"\nsamples = 4\n[render.adaptive]\nthreshold = -0.5\n") ==
          "scene.toml:5: [render.adaptive] threshold: -0.500000 must be >= 0");
    CHECK(errorOf("[render]\nsampler = \"adaptive\"\nsamples = 4\n[render.adaptive]\nwiden = 1\n") ==
          "scene.toml:5: [render.adaptive] widen: expected true or false, got an integer");
    CHECK(errorOf("[render]\nsampler = \"adaptive\"\nsamples = 4\n[render.adaptive]\nsampler = \"adaptive\"\n") ==
          "scene.toml:5: [render.adaptive] sampler: 'adaptive' is not one of random, stratified, grid, sobol, r2");
    CHECK(errorOf("[render]\nsampler = \"adaptive\"\nsamples = 4\n[render.adaptive]\nlevels = 3\n") ==
          "scene.toml:5: [render.adaptive] levels: unknown key (known keys: threshold, max_samples, widen, sampler)");
}

}

TEST_CASE("raylab scene-format lists each registered kind of object and light with its keys, read from the registry") {
    const std::string reference = sceneTablesReference();
    for (const RegisteredKind* kind : registeredKinds()) {
        CHECK(reference.find("\n[[" + kind->name + "]] # " + kind->meaning + "\n") != std::string::npos);
        for (const KindParameter& p : kind->parameters) CHECK(reference.find("#   " + p.key + ": ") != std::string::npos);
    }
    CHECK(reference.find("#   radius: number in [1.08420217e-19, 1.84467435e+19], required: its radius\n") != std::string::npos);
    CHECK(reference.find("#   color: colour [r, g, b], default white: ") != std::string::npos);
    CHECK(reference.find("#   normal: direction [x, y, z], not zero, required: ") != std::string::npos);
    // Objects first, then lights: each kind under its role's heading.
    const std::size_t lights = reference.find("\n# Lights\n");
    REQUIRE(lights != std::string::npos);
    CHECK(reference.find("\n# Objects\n") < lights);
    CHECK(reference.find("\n[[sphere]] # ") < lights);
    CHECK(reference.find("\n[[light]] # ") > lights);
}

TEST_CASE("a kind of object refuses a table its declaration accepts, at the table's or the key's line") {
    // The plane's own rule: a point or an offset, not both; the key's line for a value out of range.
    CHECK(errorOf("[[plane]]\nnormal = [0, 1, 0]\n") == "scene.toml:1: [[plane]]: a plane needs a normal, and either a point or an offset");
    CHECK(errorOf("[[sphere]]\ncenter = [0, 0, 3]\nradius = 1\ncolor = [1, 0]\n") ==
          "scene.toml:4: [[sphere]] color: expected an array of 3 numbers such as [0.0, 1.0, 0.0]");
    // A kind registered twice is refused, naming both places, a light under an object's name too
    // (a scene file's table is one or the other).
    const auto twice = [](const char* name, KindRole role) {
        registerKind({name, "again", role, {}, [](const KindValues&, Scene&) {}});
    };
    CHECK_THROWS_WITH_AS(twice("sphere", KindRole::Object), doctest::Contains("the name 'sphere' (kind of object or light) is registered twice"),
                         std::logic_error);
    CHECK_THROWS_WITH_AS(twice("sphere", KindRole::Light), doctest::Contains("the name 'sphere' (kind of object or light) is registered twice"),
                         std::logic_error);
}

TEST_CASE("objects of every kind are kept in the order read, each kind in its array") {
    const SceneDescription d = loadText("[[plane]]\nnormal = [0, 1, 0]\noffset = -1\n"
                                        "[[sphere]]\ncenter = [0, 0, 3]\nradius = 1\n[[sphere]]\ncenter = [0, 0, 6]\nradius = 2\n");
    CHECK(d.scene.objectCount() == 3);
    REQUIRE(d.scene.all<SphereGeometry>().size() == 2);
    CHECK(d.scene.all<SphereGeometry>()[0].center() == glm::vec3(0.f, 0.f, 3.f));
    CHECK(d.scene.all<SphereGeometry>()[1].radius() == 2.f);
    // A hit's object knows its kind: its normal is its kind's own.
    HitRecord hit;
    REQUIRE(d.scene.intersect(Ray{glm::vec3(0.f), glm::vec3(0.f, 0.f, 1.f)}, hit));
    CHECK(hit.object == &d.scene.all<SphereGeometry>()[0]);
    REQUIRE(d.scene.intersect(Ray{glm::vec3(0.f), glm::vec3(0.f, -1.f, 0.f)}, hit));
    CHECK(hit.object == &d.scene.all<Plane>()[0]);
    CHECK(hit.object->computeNormal(hit.position) == glm::vec3(0.f, 1.f, 0.f));
}
