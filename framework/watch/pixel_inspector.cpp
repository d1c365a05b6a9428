#include "watch/pixel_inspector.h"

#include "grader/course/run_scratch.h"
#include "grader/course/submission.h"
#include "grader/inspector/inspector_steps.h"
#include "grader/protocol/protocol.h"
#include "grader/sandbox/sandbox.h"
#include "watch/page_document.h"
#include "src/messages.h"
#include "src/scene_file.h"
#include "src/text.h"
#include "raylab/image_io.h"
#include "raylab/todo.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <set>

namespace raylab::watch {

namespace fs = std::filesystem;
using Json = nlohmann::json;
namespace inspector = grader::inspector;

namespace {

// Whether two values (numbers or lists of numbers, or words) differ beyond float precision, or
// `inBytes` in their 8 bits; NaN always differs.
bool differ(const Json& student, const Json& reference, bool inBytes) {
    if (student.is_null()) return true;
    if (reference.is_string() || reference.is_boolean()) return student != reference;
    const Json a = student.is_array() ? student : Json::array({student});
    const Json b = reference.is_array() ? reference : Json::array({reference});
    if (a.size() != b.size()) return true;
    for (std::size_t k = 0; k < a.size(); ++k) {
        if (!a[k].is_number() || !b[k].is_number()) return true;
        const double x = a[k].get<double>(), y = b[k].get<double>();
        if (inBytes ? !std::isfinite(x) || toByte(float(x)) != toByte(float(y)) : !(std::abs(x - y) <= 1e-4 * std::max(1., std::abs(y))))
            return true;
    }
    return false;
}

// The student's outputs of each call (empty where it gave none), and why the first one missing is
// missing (not done yet, an exception, a crash).
struct Answers {
    inspector::Outputs outputs;
    std::string why;
};

// Runs the agent on the calls, each a check request of its own (a stub reached by one costs that
// one alone), confined as grading confines it.
Answers askAgent(const fs::path& program, const fs::path& scenes, int lab, const std::vector<grader::protocol::Call>& calls) {
    namespace protocol = grader::protocol;
    Answers answers{inspector::Outputs(calls.size()), ""};
    if (calls.empty()) return answers;
    const grader::RunScratch scratch("inspect"); // removed at its end
    grader::SandboxLimits limits;
    limits.wallSeconds = limits.totalSeconds = 10.;
    std::string requests;
    for (std::size_t k = 0; k < calls.size(); ++k)
        requests += protocol::serialize(protocol::CheckRequest{k + 1, {calls[k]}, lab}) + "\n";
    const grader::AgentRun run = grader::runAgent({program, {}, scratch.path() / "run", {scenes}, {}, requests}, limits);
    const auto why = [&](const std::string& reason) {
        if (answers.why.empty()) answers.why = reason;
    };
    for (const std::string& line : run.lines) {
        const protocol::Parsed<protocol::Answer> parsed = protocol::parseAnswer(line);
        const std::optional<std::uint64_t> item = parsed.message ? protocol::itemOf(*parsed.message) : std::nullopt;
        if (!item || *item < 1 || *item > calls.size()) continue;
        if (const auto* values = std::get_if<protocol::Values>(&*parsed.message); values && values->outputs.size() == 1 &&
                                                                              calls[*item - 1].probe->fits(values->outputs[0]))
            answers.outputs[*item - 1] = values->outputs[0];
        if (const auto* todo = std::get_if<protocol::NotDone>(&*parsed.message))
            why(NotDoneYet(todo->lab, todo->function, todo->file, todo->line).what());
        if (const auto* failure = std::get_if<protocol::Failure>(&*parsed.message)) why(failure->message);
    }
    if (std::any_of(answers.outputs.begin(), answers.outputs.end(), [](const auto& o) { return o.empty(); })) why(run.describe());
    return answers;
}

// The rows of the answer: each quantity's reference beside the student's, the first that differs
// marked, with its formula and its place in the handout. A row computed on the reference's values of
// a row above that differs says so ("follows": from here on, the reference's ray, not the student's),
// so that the student's column never passes for what their code computed on their own values.
void addRows(Json& answer, const std::vector<inspector::Row>& rows, const Answers& answers, const grader::LabCatalog& labs) {
    const std::string handout = languageCode(language()) == std::string("fr") ? "README.fr.md" : "README.md";
    std::set<std::string> differing; // what the rows that differ so far are of ("ray", "hit")
    for (const inspector::Row& row : rows) {
        const bool framework = row.function.empty() && !row.referenceOnly;
        Json student = framework ? row.reference : row.student ? row.student(answers.outputs) : Json();
        const bool compared = !framework && !row.referenceOnly;
        const bool differs = compared && !student.is_null() && differ(student, row.reference, row.inBytes);
        if (differs && answer["first"] == -1) answer["first"] = answer["rows"].size();
        std::string follows;
        for (const std::string& taken : row.takes)
            if (follows.empty() && differing.contains(taken)) follows = tr("watch.follows." + taken);
        if (differs && !row.gives.empty()) differing.insert(row.gives);
        const grader::LabDescription* description = labs.lab(row.lab);
        answer["rows"].push_back({{"name", tr("watch.quantity." + row.key, {{"k", std::to_string(row.index)}})},
                                  {"function", row.function},
                                  {"reference", row.reference},
                                  {"student", student},
                                  {"differs", differs},
                                  {"reference_only", row.referenceOnly},
                                  {"follows", follows},
                                  {"formula", tr("watch.formula." + row.key)},
                                  {"handout", description == nullptr ? std::string()
                                                                     : "labs/" + description->id + "/" + handout + "#" +
                                                                           tr("watch.anchor." + row.key)}});
    }
}

// The labs whose steps follow a figure of lab `lab`: its own and those its figure's code uses, in
// the order of their numbers.
std::vector<const grader::LabDescription*> stepLabs(const grader::LabCatalog& labs, int lab, const grader::LabFigure* figure) {
    std::set<int> numbers{lab};
    if (figure != nullptr) numbers.insert(figure->uses.begin(), figure->uses.end());
    std::vector<const grader::LabDescription*> found;
    for (const int n : numbers)
        if (const grader::LabDescription* d = labs.lab(n)) found.push_back(d);
    return found;
}

} // namespace

PixelInspector::PixelInspector(const WatchSettings& settings, const grader::LabCatalog& labs, std::mutex& agents)
    : m_settings(settings), m_labs(labs), m_agents(agents) {}

std::string PixelInspector::inspect(const std::string& figure, int x, int y) const {
    Json answer{{"figure", printableText(figure)}, {"x", x}, {"y", y}, {"rows", Json::array()}, {"first", -1}, {"note", ""}};
    try {
        return inspectPixel(answer, figure, x, y);
    } catch (const std::exception& e) { // a scene file that cannot be read, a step's mistake: said, never the end of the watch
        answer["rows"] = Json::array();
        answer["first"] = -1;
        answer["note"] = printableText(e.what());
        return jsonText(answer);
    }
}

std::string PixelInspector::inspectPixel(Json& answer, const std::string& figure, int x, int y) const {
    const int lab = m_labs.labNumberOfFigure(figure);
    const grader::LabFigure* described = m_labs.figure(figure);
    const fs::path sceneFile = !m_settings.scenes.empty() ? m_settings.scenes / (figure + ".toml")
                               : described != nullptr      ? described->scene
                                                           : fs::path();
    std::error_code error;
    if (lab == 0 || !fs::is_regular_file(sceneFile, error)) {
        answer["note"] = tr("watch.no_figure", {{"figure", printableText(figure)}});
        return jsonText(answer);
    }
    const grader::LabDescription* own = m_labs.lab(lab);
    if (own == nullptr || !inspector::hasInspector(own->id)) {
        answer["note"] = tr("watch.no_inspector", {{"lab", std::to_string(lab)}});
        return jsonText(answer);
    }
    const SceneDescription d = loadSceneFile(sceneFile);
    if (x < 0 || y < 0 || x >= d.width || y >= d.height) {
        answer["note"] = tr("watch.outside", {{"x", std::to_string(x)}, {"y", std::to_string(y)},
                                             {"width", std::to_string(d.width)}, {"height", std::to_string(d.height)}});
        return jsonText(answer);
    }

    // Each lab's rows, from its grading folder: the camera's first, then what its ray meets.
    inspector::PixelContext pixel{d, figure, x, y, m_settings.out / "report" / "images", m_settings.references};
    inspector::Inspection asked;
    const std::vector<const grader::LabDescription*> labs = stepLabs(m_labs, lab, described);
    for (const inspector::InspectorStage stage : {inspector::InspectorStage::Ray, inspector::InspectorStage::Path})
        for (const grader::LabDescription* l : labs)
            for (const inspector::InspectorStep step : inspector::inspectorSteps(l->id, stage)) step(pixel, asked);
    if (asked.rows().empty()) {
        answer["note"] = tr("watch.not_inspected", {{"figure", printableText(figure)}, {"lab", std::to_string(lab)}});
        return jsonText(answer);
    }

    // The student's values, from the lab's agent in the grading sandbox.
    bool isolated = false;
    const std::vector<grader::AgentPlan> agents = grader::findAgents(m_settings.binDir, {lab}, isolated);
    Answers answers{inspector::Outputs(asked.calls().size()), ""};
    if (agents.empty()) {
        answers.why = tr("grade.no_agent", {{"folder", m_settings.binDir.string()}});
    } else {
        const std::lock_guard lock(m_agents); // not while a build relinks the agent
        answers = askAgent(agents.front().program, sceneFile.parent_path(), lab, asked.calls());
    }
    answer["note"] = printableText(answers.why);
    addRows(answer, asked.rows(), answers, m_labs);
    return jsonText(answer);
}

} // namespace raylab::watch
