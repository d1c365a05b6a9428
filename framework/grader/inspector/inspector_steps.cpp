#include "grader/inspector/inspector_steps.h"

#include "raylab/image_io.h"

#include <cmath>
#include <map>
#include <utility>
#include <stdexcept>

namespace raylab::grader::inspector {

namespace {

// Each lab's steps, in their order of registration. Built on first use: the registrars run at static
// initialisation, in any order of the files.
std::map<std::pair<std::string, InspectorStage>, std::vector<InspectorStep>>& steps() {
    static std::map<std::pair<std::string, InspectorStage>, std::vector<InspectorStep>> registered;
    return registered;
}

} // namespace

void registerInspectorStep(const std::string& lab, InspectorStage stage, InspectorStep step, SourcePlace where) {
    if (step == nullptr) throw std::logic_error(where.shown() + ": an inspector step of " + lab + " is null");
    steps()[{lab, stage}].push_back(step);
}

std::vector<InspectorStep> inspectorSteps(const std::string& lab, InspectorStage stage) {
    const auto found = steps().find({lab, stage});
    return found != steps().end() ? found->second : std::vector<InspectorStep>{};
}

bool hasInspector(const std::string& lab) {
    return !inspectorSteps(lab, InspectorStage::Ray).empty() || !inspectorSteps(lab, InspectorStage::Path).empty();
}

int Inspection::call(protocol::Call call) {
    m_calls.push_back(std::move(call));
    return int(m_calls.size()) - 1;
}

Json shown(double value) { return std::isfinite(value) ? Json(value) : Json(); }
Json shown(bool value) { return Json(value); }
Json shown(const glm::dvec3& value) { return Json::array({shown(value.x), shown(value.y), shown(value.z)}); }

Json PixelContext::picturePixel(const std::string& kind) const {
    std::filesystem::path file = images / (figure + "." + kind + ".png");
    std::error_code error;
    for (const std::filesystem::path& folder : references)
        if (kind == "reference" && !std::filesystem::is_regular_file(file, error)) file = folder / (figure + ".png");
    if (!std::filesystem::is_regular_file(file, error)) return {};
    try {
        const Image8 image = readImage(file);
        if (x >= image.width || y >= image.height) return {};
        const std::uint8_t* p = image.pixel(x, y);
        return Json::array({p[0] / 255., p[1] / 255., p[2] / 255.});
    } catch (const std::exception&) {
        return {};
    }
}

} // namespace raylab::grader::inspector
