#include "watch/pixel_inspector.h"

#include "grader/course/run_scratch.h"
#include "grader/course/submission.h"
#include "grader/protocol/protocol.h"
#include "grader/sandbox/sandbox.h"
#include "src/messages.h"
#include "src/scene_file.h"
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

// The default camera's ray through (sx, sy), as lab 2's handout says it: the frame u = (-1, 0, 0),
// v = (0, 1, 0), w = (0, 0, -1), the screen at distance 1.
ReferenceRay cameraRay(const SceneDescription& d, double sx, double sy) {
    const glm::dvec3 position(d.camera.position);
    const double height = 2. * std::tan(double(d.camera.fovy) / 2. * std::numbers::pi / 180.);
    const double width = height * d.width / d.height;
    const glm::dvec3 u(-1., 0., 0.), v(0., 1., 0.), w(0., 0., -1.);
    const glm::dvec3 topLeft = position - w + v * (height / 2.) - u * (width / 2.);
    const glm::dvec3 point = topLeft + sx * width * u - sy * height * v;
    return {position, glm::normalize(point - position)};
}

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

// One row: a quantity, the function of the labs that computes it, and where the handout explains it.
struct Row {
    std::string key;      // watch.quantity.<key>, watch.formula.<key>, watch.anchor.<key>
    std::string function; // the lab function; empty for the framework's own
    int lab = 0;          // whose handout
    Json reference, student;
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

grader::protocol::Call call(const char* probe, std::vector<double> inputs) {
    const grader::protocol::ProbeSpec* spec = grader::protocol::probeNamed(probe);
    if (spec == nullptr) throw std::logic_error(std::string("raylab watch: no probe ") + probe);
    return {spec, std::move(inputs)};
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

std::string PixelInspector::inspect(const std::string& figure, int x, int y) const {
    Json answer{{"figure", figure}, {"x", x}, {"y", y}, {"rows", Json::array()}, {"first", -1}, {"note", ""}};
    const int lab = m_labs.labNumberOfFigure(figure);
    const fs::path sceneFile = m_settings.scenes / (figure + ".toml");
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
    const int shading = shadingIndex(d.shading);
    const bool lab3 = shading >= 0 && d.scene.spheres.size() == 1 && d.scene.planes.empty();
    if (d.camera.lookAt || d.samples != 1 || !(lab3 || d.shading == "directions")) {
        answer["note"] = tr("watch.not_inspected", {{"figure", figure}});
        return answer.dump();
    }

    // The reference, in double, and the calls that ask the student's code for the same quantities.
    const double sx = (x + 0.5) / d.width, sy = (y + 0.5) / d.height;
    const ReferenceRay ray = cameraRay(d, sx, sy);
    std::vector<Row> rows{{"screen", "", 2, Json::array({sx, sy}), Json::array({sx, sy})},
                          {"origin", "PerspectiveCamera::generateRay", 2, vec(ray.origin), {}},
                          {"direction", "PerspectiveCamera::generateRay", 2, vec(ray.direction), {}}};
    std::vector<double> rayInputs{double(d.width), double(d.height), double(d.camera.fovy)};
    append(rayInputs, glm::dvec3(d.camera.position));
    rayInputs.insert(rayInputs.end(), {sx, sy});
    std::vector<grader::protocol::Call> calls{call("generateRay", rayInputs)};
    if (lab3) {
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
        calls.push_back(call("intersect", intersectInputs));
        rows.push_back({"hit", "SphereGeometry::intersect", 3, t.has_value(), {}});
        if (t) {
            rows.push_back({"t", "SphereGeometry::intersect", 3, *t, {}});
            rows.push_back({"position", "SphereGeometry::intersect", 3, vec(position), {}});
            std::vector<double> normalInputs = sphereInputs;
            append(normalInputs, position);
            calls.push_back(call("computeNormal", normalInputs));
            rows.push_back({"normal", "SphereGeometry::computeNormal", 3, vec(normal), {}});
        }
        std::vector<double> liInputs{double(shading)};
        liInputs.insert(liInputs.end(), sphereInputs.begin(), sphereInputs.end());
        append(liInputs, colour);
        append(liInputs, background);
        append(liInputs, ray.origin);
        append(liInputs, ray.direction);
        calls.push_back(call("Li", liInputs));
        rows.push_back({"colour", "RayCastIntegrator::Li", 3, vec(seen), {}});
    }

    // The student's values, in the rows' order of the calls' outputs.
    bool isolated = false;
    const std::vector<grader::AgentPlan> agents = grader::findAgents(m_settings.binDir, {lab}, isolated);
    Answers answers{std::vector<std::vector<double>>(calls.size()), ""};
    if (agents.empty()) {
        answers.why = tr("grade.no_agent", {{"folder", m_settings.binDir.string()}});
    } else {
        const std::lock_guard lock(m_agents); // not while a build relinks the agent
        answers = askAgent(agents.front().program, m_settings.scenes, lab, calls);
    }
    const auto& o = answers.outputs;
    rows[1].student = numbers(o[0], 0, 3);
    rows[2].student = numbers(o[0], 3, 3);
    if (lab3) {
        std::size_t next = 3;
        rows[next++].student = o[1].empty() ? Json() : Json(o[1][0] != 0.);
        if (rows[next].key == "t") {
            rows[next++].student = numbers(o[1], 1, 1);
            rows[next++].student = numbers(o[1], 2, 3);
            rows[next++].student = numbers(o[2], 0, 3);
        }
        rows[next].student = numbers(o.back(), 0, 3);
    }
    answer["note"] = printableText(answers.why);

    const std::string handout = languageCode(language()) == std::string("fr") ? "README.fr.md" : "README.md";
    for (const Row& row : rows) {
        const grader::LabDescription* description = m_labs.lab(row.lab);
        const bool framework = row.function.empty();
        const bool differs = !framework && !row.student.is_null() &&
                             (row.reference.is_boolean() ? row.student != row.reference : differ(row.student, row.reference));
        if (differs && answer["first"] == -1) answer["first"] = answer["rows"].size();
        answer["rows"].push_back({{"name", tr("watch.quantity." + row.key)},
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
