#include "grader/judge/diagnosis.h"

#include "src/messages.h"
#include "src/toml_reader.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace raylab::grader {

namespace fs = std::filesystem;

std::string Diagnosis::text() const {
    if (!mistake) return "";
    std::string text = tr("diagnosis.matches", mistake->args());
    if (alike) text += tr("diagnosis.or_alike", alike->args());
    return text;
}

const std::string& Mistake::name() const { return language() == Language::Fr ? nameFr : nameEn; }
const std::string& Mistake::hint() const { return language() == Language::Fr ? hintFr : hintEn; }

std::vector<std::pair<std::string_view, std::string>> Mistake::args() const {
    const std::string shown = label.empty() ? "" : (language() == Language::Fr ? "E" : "M") + label + " ";
    return {{"name", name()}, {"hint", hint()}, {"label", shown}, {"lab", std::to_string(lab)}, {"function", function}};
}

namespace {

Mistake readMistake(const TomlReader& r, const toml::table& m, const std::string& where) {
    r.onlyKeys(m, where, {"id", "name", "name_fr", "hint", "hint_fr", "label", "lab", "function", "check", "check_hint"});
    Mistake mistake;
    mistake.id = r.text(m, where, "id");
    // Its signatures are in the folder mistakes/<id>: a name that is a path would reach elsewhere.
    if (mistake.id.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-") != std::string::npos)
        r.fail(m.get("id"), std::string(where) + "id", tr("toml.folder_name", {{"value", mistake.id}}));
    mistake.nameEn = r.text(m, where, "name");
    mistake.nameFr = r.text(m, where, "name_fr");
    mistake.hintEn = r.text(m, where, "hint");
    mistake.hintFr = r.text(m, where, "hint_fr");
    mistake.label = r.string(m, where, "label").value_or("");
    mistake.lab = int(r.requiredInteger(m, where, "lab", 1, std::numeric_limits<int>::max()));
    mistake.function = r.text(m, where, "function");
    mistake.check = r.string(m, where, "check").value_or("");
    mistake.checkHint = r.string(m, where, "check_hint").value_or("");
    return mistake;
}

// One folder's catalogue, appended to `mistakes`.
void loadCatalogue(const fs::path& referenceFolder, std::vector<Mistake>& mistakes) {
    const fs::path file = referenceFolder / "mistakes.toml";
    std::error_code error;
    if (!fs::exists(file, error)) return;
    const toml::table root = parseTomlFile(file);
    const TomlReader r(file);
    r.onlyKeys(root, "", {"mistake"});
    const std::vector<const toml::table*> list = r.tables(root, "mistake");
    if (list.empty()) r.fail(nullptr, "[[mistake]]", tr("toml.missing"));
    for (std::size_t k = 0; k < list.size(); ++k) {
        const std::string where = "[[mistake]] #" + std::to_string(k + 1) + " ";
        Mistake mistake = readMistake(r, *list[k], where);
        for (const Mistake& other : mistakes)
            if (other.id == mistake.id)
                r.fail(list[k]->get("id"), where + "id",
                       tr("toml.mistake_twice", {{"id", mistake.id}, {"file", (other.folder / "mistakes.toml").string()}}));
        mistake.folder = referenceFolder;
        mistakes.push_back(std::move(mistake));
    }
}

// The files of `folder` (none when there is no such folder), by name: the same order on every system.
std::vector<fs::path> sortedEntries(const fs::path& folder) {
    std::vector<fs::path> entries;
    std::error_code error;
    if (fs::is_directory(folder, error))
        for (const auto& entry : fs::directory_iterator(folder)) entries.push_back(entry.path());
    std::sort(entries.begin(), entries.end());
    return entries;
}

// The signatures kept in one reference folder, whichever catalogue lists their mistakes.
void loadSignatures(const fs::path& referenceFolder, std::vector<Mistake>& mistakes) {
    for (const fs::path& folder : sortedEntries(referenceFolder / "mistakes")) {
        const auto mistake = std::find_if(mistakes.begin(), mistakes.end(),
                                          [&](const Mistake& m) { return m.id == folder.filename().string(); });
        if (mistake == mistakes.end()) continue;
        for (const fs::path& file : sortedEntries(folder))
            if (file.extension() == ".png") mistake->signatures.emplace_back(file.stem().string(), readImage(file));
    }
}

} // namespace

std::vector<Mistake> loadMistakes(const std::vector<fs::path>& referenceFolders) {
    std::vector<Mistake> mistakes;
    for (const fs::path& folder : referenceFolders) loadCatalogue(folder, mistakes);
    for (const fs::path& folder : referenceFolders) loadSignatures(folder, mistakes);
    return mistakes;
}

fs::path signatureFolder(const std::vector<fs::path>& referenceFolders, const std::string& figure, const std::string& mistake) {
    std::error_code error;
    const auto holder = std::find_if(referenceFolders.begin(), referenceFolders.end(),
                                     [&](const fs::path& folder) { return fs::exists(folder / (figure + ".toml"), error); });
    return (holder != referenceFolders.end() ? *holder : referenceFolders.at(0)) / "mistakes" / mistake;
}

Image8 downsample(const Image8& image) {
    const int s = kSignatureScale;
    Image8 small{image.width / s, image.height / s, {}};
    small.rgb.resize(std::size_t(small.width) * small.height * 3);
    for (int j = 0; j < small.height; ++j)
        for (int i = 0; i < small.width; ++i)
            for (int c = 0; c < 3; ++c) {
                int sum = 0;
                for (int y = 0; y < s; ++y)
                    for (int x = 0; x < s; ++x) sum += image.pixel(i * s + x, j * s + y)[c];
                small.rgb[3 * (std::size_t(j) * small.width + i) + c] = std::uint8_t((sum + s * s / 2) / (s * s));
            }
    return small;
}

namespace {

double meanAbsoluteDifference(const Image8& a, const Image8& b) {
    if (a.width != b.width || a.height != b.height || a.rgb.empty()) return std::numeric_limits<double>::infinity();
    double sum = 0.;
    for (std::size_t k = 0; k < a.rgb.size(); ++k) sum += std::abs(int(a.rgb[k]) - int(b.rgb[k]));
    return sum / double(a.rgb.size());
}

} // namespace

Diagnosis diagnose(const std::vector<Mistake>& mistakes, const std::string& figure, const Image8& student,
                   const Image8& reference, const std::function<bool(const Mistake&)>& suspect) {
    Diagnosis best;
    const Image8 small = downsample(student);
    best.referenceDistance = meanAbsoluteDifference(small, downsample(reference));
    best.distance = std::numeric_limits<double>::infinity();
    double alikeDistance = best.distance;
    for (const Mistake& m : mistakes)
        for (const auto& [id, signature] : m.signatures) {
            if (id != figure || !suspect(m)) continue;
            const double d = meanAbsoluteDifference(small, signature);
            if (d < best.distance) {
                best.alike = best.mistake;
                alikeDistance = best.distance;
                best.distance = d;
                best.mistake = &m;
            } else if (d < alikeDistance) {
                alikeDistance = d;
                best.alike = &m;
            }
        }
    if (!(alikeDistance <= best.distance + 0.25)) best.alike = nullptr;
    // A fit: within 3 LSB on average, and at most a third of the distance to the reference.
    if (best.mistake && !(best.distance <= 3. && best.distance <= best.referenceDistance / 3.)) best.mistake = best.alike = nullptr;
    return best;
}

} // namespace raylab::grader
