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

int Inspection::call(const protocol::ProbeSpec* probe, std::vector<double> inputs) {
    if (probe == nullptr) throw std::logic_error("raylab watch: an inspector step asks a probe that is not registered");
    m_calls.push_back({probe, std::move(inputs)});
    return int(m_calls.size()) - 1;
}

StudentValue values(int call, std::size_t from, std::size_t count) {
    return [=](const Outputs& outputs) -> Json {
        if (call < 0 || std::size_t(call) >= outputs.size()) return {};
        const std::vector<double>& out = outputs[std::size_t(call)];
        if (count == 0) return out.size() > from ? Json(out[from] != 0.) : Json();
        if (out.size() < from + count) return {};
        Json list = Json::array();
        for (std::size_t k = from; k < from + count; ++k) list.push_back(std::isfinite(out[k]) ? Json(out[k]) : Json());
        return count == 1 ? list.at(0) : list;
    };
}

Json vec(const glm::dvec3& v) { return Json::array({v.x, v.y, v.z}); }

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
