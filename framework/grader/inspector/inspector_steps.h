#pragma once
// The pixel inspector's rows, lab by lab (raylab watch's page, framework/watch/pixel_inspector.h): for
// one pixel of a figure, each quantity a lab computes on the way to its colour, the reference's value
// beside the student's. Each lab's grading folder registers its step (framework/grader/labs/<lab>/
// inspector.cpp), which knows its lab's functions and formulas; the framework knows none:
//
//   RAYLAB_REGISTER_INSPECTOR_STEP(InspectorStage::Ray, lookAtRows);
//
// A figure's steps are those of its lab and of the labs its code uses (lab.toml), run on one
// PixelContext, the Ray steps then the Path steps, each in the order of the labs' numbers: a camera's
// step makes the reference's ray, a later one follows it. The reference's values are computed in the parent, in double, from the handouts' formulas; the
// student's come from their code in the grading sandbox, each a call of a lab probe on the
// reference's inputs (the intersection on the reference's ray), so that the first value that differs
// names the function that is wrong. A row computed on the reference's values of an earlier row says so
// on the page when that earlier row differs ("takes" and "gives" below).
//
// The lab is the grading folder's (RAYLAB_LAB_ID, its folder's name, which CMake defines for it).

#include "grader/protocol/probe.h"
#include "src/name_registry.h"
#include "src/scene_file.h"

#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <functional>
#include <type_traits>
#include <optional>
#include <string>
#include <vector>

namespace raylab::grader::inspector {

using Json = nlohmann::json;
// The student's outputs of each call of the inspection, in its order; empty where it gave none.
using Outputs = std::vector<std::vector<double>>;
// A row's student value from the outputs; null when their code gave none.
using StudentValue = std::function<Json(const Outputs&)>;

struct Row {
    std::string key{};    // watch.quantity.<key>, watch.formula.<key>, watch.anchor.<key> (the lab's messages)
    std::string function{}; // the lab function that computes it; empty: the framework's (the student's value is the reference's)
    int lab = 0;          // whose handout explains it
    Json reference{};
    StudentValue student{}; // none: no function of the student gives this value (see referenceOnly)
    int index = 0;        // which one, for a quantity listed several times ({k} in its name, from 1)
    // The reference's path only: what the reference computes on the way (a shadow ray), which the
    // student's code does not hand back; shown as the reference's, never as the student's.
    bool referenceOnly = false;
    std::string gives{};            // what this row is of the pixel's path ("ray", "hit"), when a later row takes it
    std::vector<std::string> takes{}; // the reference's values it is computed on ("ray", "hit", ...)
    // Compared as a picture holds them, each value rounded to 8 bits (raylab/image_io.h's toByte):
    // a reference read from a picture, beside the student's exact value.
    bool inBytes = false;
};

// The reference's ray through a pixel, in double.
struct ReferenceRay {
    glm::dvec3 origin{0.}, direction{0.};
};

struct PixelContext {
    const SceneDescription& scene;
    std::string figure;
    int x = 0, y = 0;
    std::filesystem::path images{}; // the last grade's pictures: <figure>.student.png, <figure>.reference.png
    std::vector<std::filesystem::path> references{}; // the grader's references, each lab's folder: <figure>.png
    std::optional<ReferenceRay> ray{}; // made by the step of the camera, for the steps after it
    bool coloured = false;           // a step has given the pixel's colour: a later one does not give another

    // The pixel of the last grade's picture `kind` ("student", "reference") as a colour (0 to 1 a
    // channel); the reference's is the grader's own where no grade has written it; null when there is
    // none.
    Json picturePixel(const std::string& kind) const;
};

class Inspection {
public:
    // Asks the student's code a probe's call (on the reference's inputs): the index of the call, for answerOf().
    int call(protocol::Call call);
    void add(Row row) { m_rows.push_back(std::move(row)); }

    const std::vector<Row>& rows() const { return m_rows; }
    const std::vector<protocol::Call>& calls() const { return m_calls; }

private:
    std::vector<Row> m_rows;
    std::vector<protocol::Call> m_calls;
};

// A value as the page shows it: a number, a list of three, a yes or no; a number that is not finite as null.
Json shown(double value);
Json shown(bool value);
Json shown(const glm::dvec3& value);
inline Json shown(Json value) { return value; }

// The student's value from call `call` of `probe`: what `get` (a member of its answer, or any
// function of it, which may give Json, null for none) takes from the answer; null when the call gave none.
template <class Answer, class... Inputs, class Get = std::identity>
StudentValue answerOf(const protocol::Probe<Answer(Inputs...)>& probe, int call, Get get = {}) {
    return [&probe, call, get](const Outputs& outputs) -> Json {
        if (call < 0 || std::size_t(call) >= outputs.size() || outputs[std::size_t(call)].empty()) return {};
        return shown(std::invoke(get, probe.answer(outputs[std::size_t(call)])));
    };
}

// A lab's step: adds its rows for the pixel (none when the figure is not one it follows).
using InspectorStep = void (*)(PixelContext& pixel, Inspection& inspection);

enum class InspectorStage {
    Ray,  // the camera's: makes the pixel's ray (PixelContext::ray) or its samples
    Path, // what the ray meets, after every Ray step
};

// Adds a step of lab `lab`.
void registerInspectorStep(const std::string& lab, InspectorStage stage, InspectorStep step, SourcePlace where);
// The steps of lab `lab` at `stage`, in their order; empty when it registers none.
std::vector<InspectorStep> inspectorSteps(const std::string& lab, InspectorStage stage);
// Whether lab `lab` registers a step.
bool hasInspector(const std::string& lab);

struct InspectorStepRegistrar {
    InspectorStepRegistrar(const std::string& lab, InspectorStage stage, InspectorStep step, SourcePlace where = SourcePlace::here()) {
        registerInspectorStep(lab, stage, step, where);
    }
};

} // namespace raylab::grader::inspector

// At namespace scope in a lab's inspector.cpp.
#define RAYLAB_REGISTER_INSPECTOR_STEP(stage, step)                                                                    \
    RAYLAB_REGISTRAR(::raylab::grader::inspector::InspectorStepRegistrar)(RAYLAB_LAB_ID, (stage), (step))
