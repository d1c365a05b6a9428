#include "watch/pixel_inspector.h"

#include "grader/course/run_scratch.h"
#include "grader/course/submission.h"
#include "grader/protocol/protocol.h"
#include "grader/sandbox/sandbox.h"
#include "src/messages.h"
#include "src/scene_file.h"
#include "raylab/image_io.h"
#include "raylab/sampler.h"
#include "src/text.h"
#include "raylab/todo.h"

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

namespace raylab::watch {

namespace fs = std::filesystem;
using Json = nlohmann::json;

namespace {

struct ReferenceRay {
    glm::dvec3 origin, direction;
};

// The figure's camera as the handouts build it: lab 2's default frame (u = (-1, 0, 0), v = (0, 1, 0),
// w = (0, 0, -1)) or lab 4's lookAt frame (w = normalize(position - target), u = normalize(cross(up,
// w)), v = cross(w, u)), the screen at distance 1.
struct ReferenceCamera {
    glm::dvec3 position, u{-1., 0., 0.}, v{0., 1., 0.}, w{0., 0., -1.}, topLeft;
    double height, width;

    explicit ReferenceCamera(const SceneDescription& d) : position(d.camera.position) {
        if (d.camera.lookAt) {
            w = glm::normalize(position - glm::dvec3(d.camera.target));
            u = glm::normalize(glm::cross(glm::dvec3(d.camera.up), w));
            v = glm::cross(w, u);
        }
        height = 2. * std::tan(double(d.camera.fovy) / 2. * std::numbers::pi / 180.);
        width = height * d.width / d.height;
        topLeft = position - w + v * (height / 2.) - u * (width / 2.);
    }
    // The ray through the screen point (sx, sy).
    ReferenceRay ray(double sx, double sy) const {
        return {position, glm::normalize(topLeft + sx * width * u - sy * height * v - position)};
    }
};

// The nearest t >= 0 where the ray meets the sphere (lab 3's "which root"); nullopt on a miss.
std::optional<double> hitDistance(const SphereGeometry& s, const ReferenceRay& r) {
    const glm::dvec3 oc = r.origin - glm::dvec3(s.center());
    const double a = glm::dot(r.direction, r.direction), b = glm::dot(oc, r.direction);
    const double radius = s.radius();
    const double disc = b * b - a * (glm::dot(oc, oc) - radius * radius);
    if (disc < 0.) return std::nullopt;
    const double nearRoot = (-b - std::sqrt(disc)) / a, farRoot = (-b + std::sqrt(disc)) / a;
    if (nearRoot >= 0.) return nearRoot;
    if (farRoot >= 0.) return farRoot;
    return std::nullopt;
}

Json vec(const glm::dvec3& v) { return Json::array({v.x, v.y, v.z}); }

// Whether two values (numbers or lists of numbers) differ beyond float precision; NaN always differs.
bool differ(const Json& student, const Json& reference) {
    if (student.is_null()) return true;
    const Json a = student.is_array() ? student : Json::array({student});
    const Json b = reference.is_array() ? reference : Json::array({reference});
    if (a.size() != b.size()) return true;
    for (std::size_t k = 0; k < a.size(); ++k) {
        if (!a[k].is_number()) return true;
        const double x = a[k].get<double>(), y = b[k].get<double>();
        if (!(std::abs(x - y) <= 1e-4 * std::max(1., std::abs(y)))) return true;
    }
    return false;
}

// `count` outputs from `from` (one: a number, else a list), a value that is not finite as JSON null;
// null when the call gave no outputs.
Json numbers(const std::vector<double>& out, std::size_t from, std::size_t count) {
    if (out.size() < from + count) return {};
    Json values = Json::array();
    for (std::size_t k = from; k < from + count; ++k) values.push_back(std::isfinite(out[k]) ? Json(out[k]) : Json());
    return count == 1 ? values.at(0) : values;
}

// One row: a quantity, the function of the labs that computes it, where the handout explains it,
// and which outputs of which call are the student's value of it.
struct Row {
    std::string key;      // watch.quantity.<key>, watch.formula.<key>, watch.anchor.<key>
    std::string function; // the lab function; empty for the framework's own (then the student's is the reference)
    int lab = 0;          // whose handout
    Json reference;
    int call = -1;        // the call whose outputs hold the student's value; -1: none
    std::size_t from = 0, count = 0; // those outputs; count 0: a yes or no (outputs[from] != 0)
    Json student = {};    // when no call gives it (a pixel of the student's picture)
    int index = 0;        // which one, for a quantity listed several times (lab 5's samples, from 1)
};

// The student's outputs of each call (empty where it gave none), and why the first one missing is
// missing (not done yet, an exception, a crash).
struct Answers {
    std::vector<std::vector<double>> outputs;
    std::string why;
};

// Runs the agent on the calls, each a check request of its own (a stub reached by one costs that
// one alone), confined as grading confines it.
Answers askAgent(const fs::path& program, const fs::path& scenes, int lab, const std::vector<grader::protocol::Call>& calls) {
    namespace protocol = grader::protocol;
    const grader::RunScratch scratch("inspect"); // removed at its end
    grader::SandboxLimits limits;
    limits.wallSeconds = limits.totalSeconds = 10.;
    std::string requests;
    for (std::size_t k = 0; k < calls.size(); ++k)
        requests += protocol::serialize(protocol::CheckRequest{k + 1, {calls[k]}, lab}) + "\n";
    const grader::AgentRun run = grader::runAgent({program, {}, scratch.path() / "run", {scenes}, {}, requests}, limits);
    Answers answers{std::vector<std::vector<double>>(calls.size()), ""};
    const auto why = [&](const std::string& reason) {
        if (answers.why.empty()) answers.why = reason;
    };
    for (const std::string& line : run.lines) {
        const protocol::Parsed<protocol::Answer> parsed = protocol::parseAnswer(line);
        const std::optional<std::uint64_t> item = parsed.message ? protocol::itemOf(*parsed.message) : std::nullopt;
        if (!item || *item < 1 || *item > calls.size()) continue;
        if (const auto* values = std::get_if<protocol::Values>(&*parsed.message); values && values->outputs.size() == 1 &&
                                                                              protocol::outputsValid(*calls[*item - 1].probe, calls[*item - 1].inputs, values->outputs[0]))
            answers.outputs[*item - 1] = values->outputs[0];
        if (const auto* todo = std::get_if<protocol::NotDone>(&*parsed.message))
            why(NotDoneYet(todo->lab, todo->function, todo->file, todo->line).what());
        if (const auto* failure = std::get_if<protocol::Failure>(&*parsed.message)) why(failure->message);
    }
    if (std::any_of(answers.outputs.begin(), answers.outputs.end(), [](const auto& o) { return o.empty(); })) why(run.describe());
    return answers;
}

void append(std::vector<double>& inputs, const glm::dvec3& v) { inputs.insert(inputs.end(), {v.x, v.y, v.z}); }

// Lab 3's shadings as the probe Li numbers them (raylab/integrator.h's Shading); -1 for another.
int shadingIndex(const std::string& shading) {
    if (shading == "flat") return 0;
    if (shading == "placeholder_normal") return 1;
    if (shading == "cosine") return 2;
    return -1;
}

// colour * max(-d.n, 0), lab 3's shading.
glm::dvec3 cosineShade(const glm::dvec3& colour, const glm::dvec3& d, const glm::dvec3& n) {
    return colour * std::max(-glm::dot(d, n), 0.);
}

} // namespace

PixelInspector::PixelInspector(const WatchSettings& settings, const grader::LabCatalog& labs, std::mutex& agents)
    : m_settings(settings), m_labs(labs), m_agents(agents) {}

namespace {

// What one pixel's inspection asks and expects: the rows and the calls that give their student values.
struct Inspection {
    std::vector<Row> rows;
    std::vector<grader::protocol::Call> calls;
    int call(const char* probe, std::vector<double> inputs) {
        const grader::protocol::ProbeSpec* spec = grader::protocol::probeNamed(probe);
        if (spec == nullptr) throw std::logic_error(std::string("raylab watch: no probe ") + probe);
        calls.push_back({spec, std::move(inputs)});
        return int(calls.size()) - 1;
    }
};

// Lab 2's camera (the default frame): the ray through (sx, sy), asked of generateRay.
void askDefaultCamera(Inspection& a, const SceneDescription& d, double sx, double sy, const ReferenceRay& ray) {
    std::vector<double> in{double(d.width), double(d.height), double(d.camera.fovy)};
    append(in, glm::dvec3(d.camera.position));
    in.insert(in.end(), {sx, sy});
    const int c = a.call("generateRay", in);
    a.rows.push_back({"origin", "PerspectiveCamera::generateRay", 2, vec(ray.origin), c, 0, 3});
    a.rows.push_back({"direction", "PerspectiveCamera::generateRay", 2, vec(ray.direction), c, 3, 3});
}

// Lab 4's lookAt camera: its frame and its screen's top-left corner, asked of the constructor.
void askLookAt(Inspection& a, const SceneDescription& d, const ReferenceCamera& camera) {
    std::vector<double> in{double(d.width), double(d.height)};
    append(in, glm::dvec3(d.camera.position));
    append(in, glm::dvec3(d.camera.target));
    append(in, glm::dvec3(d.camera.up));
    in.push_back(d.camera.fovy);
    const int c = a.call("lookAt", in); // u, v, w, position, height, width, topLeft
    a.rows.push_back({"u", "PerspectiveCamera::PerspectiveCamera", 4, vec(camera.u), c, 0, 3});
    a.rows.push_back({"v", "PerspectiveCamera::PerspectiveCamera", 4, vec(camera.v), c, 3, 3});
    a.rows.push_back({"w", "PerspectiveCamera::PerspectiveCamera", 4, vec(camera.w), c, 6, 3});
    a.rows.push_back({"top_left", "PerspectiveCamera::PerspectiveCamera", 4, vec(camera.topLeft), c, 14, 3});
}

// Lab 3: the hit of the reference ray, the normal at the reference hit and the colour, each asked of
// the student's function with the reference's inputs.
void askSphere(Inspection& a, const SceneDescription& d, int shading, const ReferenceRay& ray) {
    const SphereGeometry& sphere = d.scene.spheres.front();
    const glm::dvec3 centre(sphere.center()), colour(sphere.color()), background(d.scene.background);
    const std::optional<double> t = hitDistance(sphere, ray);
    const glm::dvec3 position = t ? ray.origin + *t * ray.direction : glm::dvec3(0.);
    const glm::dvec3 normal = (position - centre) / double(sphere.radius());
    glm::dvec3 seen = background;
    if (t && shading == 0) seen = colour;
    if (t && shading == 1) {
        glm::dvec3 n = glm::normalize(glm::dvec3(1.));
        if (glm::dot(ray.direction, n) > 0.) n = -n;
        seen = cosineShade(colour, ray.direction, n);
    }
    if (t && shading == 2) seen = cosineShade(colour, ray.direction, normal);
    std::vector<double> sphereInputs;
    append(sphereInputs, centre);
    sphereInputs.push_back(sphere.radius());
    std::vector<double> intersectInputs = sphereInputs;
    append(intersectInputs, ray.origin);
    append(intersectInputs, ray.direction);
    intersectInputs.insert(intersectInputs.end(), {0., std::numeric_limits<double>::infinity()});
    const int hit = a.call("intersect", intersectInputs); // hit, t, position
    a.rows.push_back({"hit", "SphereGeometry::intersect", 3, t.has_value(), hit, 0, 0});
    if (t) {
        a.rows.push_back({"t", "SphereGeometry::intersect", 3, *t, hit, 1, 1});
        a.rows.push_back({"position", "SphereGeometry::intersect", 3, vec(position), hit, 2, 3});
        std::vector<double> normalInputs = sphereInputs;
        append(normalInputs, position);
        a.rows.push_back({"normal", "SphereGeometry::computeNormal", 3, vec(normal), a.call("computeNormal", normalInputs), 0, 3});
    }
    std::vector<double> liInputs{double(shading)};
    liInputs.insert(liInputs.end(), sphereInputs.begin(), sphereInputs.end());
    append(liInputs, colour);
    append(liInputs, background);
    append(liInputs, ray.origin);
    append(liInputs, ray.direction);
    a.rows.push_back({"colour", "RayCastIntegrator::Li", 3, vec(seen), a.call("Li", liInputs), 0, 3});
}

// The most samples a pixel's inspection lists one by one.
constexpr int kListedSamples = 8;

// Lab 5: the pixel's screen points and their average, asked of renderPixel (with a camera that
// records the points and an integrator whose colour is the point: the average is the mean point);
// the reference's from the framework's sampler with the scene's seed, as the figure draws them.
void askSamples(Inspection& a, const SceneDescription& d, int x, int y) {
    PixelSampler sampler(d.sampler, d.samples, d.seed, x, y, d.width);
    glm::dvec3 mean(0.);
    std::vector<glm::dvec2> points;
    for (int k = 0; k < d.samples; ++k) {
        const glm::vec2 offset = sampler.next2D();
        points.emplace_back((float(x) + offset.x) / float(d.width), (float(y) + offset.y) / float(d.height));
        mean += glm::dvec3(points.back(), 1.) / double(d.samples);
    }
    const int c = a.call("renderPixel", {double(d.width), double(d.height), double(x), double(y), double(d.samples), double(d.seed)});
    a.rows.push_back({"samples", "Renderer::renderPixel", 5, d.samples, c, 0, 1});
    for (int k = 0; k < std::min(d.samples, kListedSamples); ++k)
        a.rows.push_back({"sample", "Renderer::renderPixel", 5, Json::array({points[std::size_t(k)].x, points[std::size_t(k)].y}), c,
                          4 + 2 * std::size_t(k), 2, {}, k + 1});
    a.rows.push_back({"average", "Renderer::renderPixel", 5, vec(mean), c, 1, 3});
}

// A pixel of a picture of the watch's folder, as colour (0 to 1 a channel); null when there is none.
Json picturePixel(const fs::path& file, int x, int y) {
    std::error_code error;
    if (!fs::is_regular_file(file, error)) return {};
    try {
        const Image8 image = readImage(file);
        if (x >= image.width || y >= image.height) return {};
        const std::uint8_t* p = image.pixel(x, y);
        return Json::array({p[0] / 255., p[1] / 255., p[2] / 255.});
    } catch (const std::exception&) {
        return {};
    }
}

} // namespace

std::string PixelInspector::inspect(const std::string& figure, int x, int y) const {
    Json answer{{"figure", figure}, {"x", x}, {"y", y}, {"rows", Json::array()}, {"first", -1}, {"note", ""}};
    const int lab = m_labs.labNumberOfFigure(figure);
    const grader::LabFigure* described = m_labs.figure(figure);
    const fs::path sceneFile = !m_settings.scenes.empty() ? m_settings.scenes / (figure + ".toml")
                               : described != nullptr      ? described->scene
                                                           : fs::path();
    std::error_code error;
    if (lab == 0 || !fs::is_regular_file(sceneFile, error)) {
        answer["note"] = tr("watch.no_figure", {{"figure", printableText(figure)}});
        return answer.dump();
    }
    const SceneDescription d = loadSceneFile(sceneFile);
    if (x < 0 || y < 0 || x >= d.width || y >= d.height) {
        answer["note"] = tr("watch.outside", {{"x", std::to_string(x)}, {"y", std::to_string(y)},
                                             {"width", std::to_string(d.width)}, {"height", std::to_string(d.height)}});
        return answer.dump();
    }
    // What the inspector follows: one sphere shaded by lab 3 (or lab 2's directions), seen by the
    // default or a lookAt camera, one sample a pixel or lab 5's random samples.
    const int shading = shadingIndex(d.shading);
    const bool sphere = shading >= 0 && d.scene.spheres.size() == 1 && d.scene.planes.empty();
    const bool samples = d.samples > 1 && d.sampler == SamplerKind::Random && !d.camera.lookAt;
    if (!(sphere || d.shading == "directions") || (d.samples != 1 && !samples)) {
        answer["note"] = tr("watch.not_inspected", {{"figure", figure}});
        return answer.dump();
    }

    // The reference, in double, and the calls that ask the student's code for the same quantities.
    Inspection a;
    if (samples) {
        askSamples(a, d, x, y);
        const fs::path images = m_settings.out / "report" / "images";
        Row colour{"picture", "", 5, picturePixel(images / (figure + ".reference.png"), x, y)};
        colour.function = "Renderer::renderPixel";
        colour.student = picturePixel(images / (figure + ".student.png"), x, y);
        a.rows.push_back(colour);
    } else {
        const double sx = (x + 0.5) / d.width, sy = (y + 0.5) / d.height;
        const ReferenceCamera camera(d);
        const ReferenceRay ray = camera.ray(sx, sy);
        a.rows.push_back({"screen", "", 2, Json::array({sx, sy})});
        if (d.camera.lookAt) askLookAt(a, d, camera);
        else askDefaultCamera(a, d, sx, sy, ray);
        if (sphere) askSphere(a, d, shading, ray);
    }

    // The student's values, from the lab's agent in the grading sandbox.
    bool isolated = false;
    const std::vector<grader::AgentPlan> agents = grader::findAgents(m_settings.binDir, {lab}, isolated);
    Answers answers{std::vector<std::vector<double>>(a.calls.size()), ""};
    if (agents.empty()) {
        answers.why = tr("grade.no_agent", {{"folder", m_settings.binDir.string()}});
    } else {
        const std::lock_guard lock(m_agents); // not while a build relinks the agent
        answers = askAgent(agents.front().program, sceneFile.parent_path(), lab, a.calls);
    }
    answer["note"] = printableText(answers.why);

    const std::string handout = languageCode(language()) == std::string("fr") ? "README.fr.md" : "README.md";
    for (Row& row : a.rows) {
        const bool framework = row.function.empty();
        if (framework) row.student = row.reference;
        if (row.call >= 0) {
            const std::vector<double>& out = answers.outputs[std::size_t(row.call)];
            row.student = row.count == 0 ? (out.size() > row.from ? Json(out[row.from] != 0.) : Json())
                                         : numbers(out, row.from, row.count);
        }
        const bool differs = !framework && !row.student.is_null() &&
                             (row.reference.is_boolean() ? row.student != row.reference : differ(row.student, row.reference));
        if (differs && answer["first"] == -1) answer["first"] = answer["rows"].size();
        const grader::LabDescription* description = m_labs.lab(row.lab);
        answer["rows"].push_back({{"name", tr("watch.quantity." + row.key, {{"k", std::to_string(row.index)}})},
                                  {"function", row.function},
                                  {"reference", row.reference},
                                  {"student", row.student},
                                  {"differs", differs},
                                  {"formula", tr("watch.formula." + row.key)},
                                  {"handout", description == nullptr ? std::string()
                                                                     : "labs/" + description->id + "/" + handout + "#" +
                                                                           tr("watch.anchor." + row.key)}});
    }
    return answer.dump();
}

} // namespace raylab::watch
