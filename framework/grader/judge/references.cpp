#include "grader/judge/references.h"

#include "src/atomic_file.h"
#include "src/messages.h"
#include "src/toml_reader.h"

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace raylab::grader {

namespace fs = std::filesystem;

const FigureReference* ReferenceSet::find(const std::string& id) const {
    for (const FigureReference& f : figures)
        if (f.id == id) return &f;
    return nullptr;
}

namespace {

[[noreturn]] void bad(const fs::path& file, const std::string& problem) {
    throw std::runtime_error(file.string() + ": " + problem);
}

Image8 readSized(const fs::path& file, int width, int height) {
    Image8 image = readImage(file);
    if (image.width != width || image.height != height)
        bad(file, "is " + std::to_string(image.width) + " x " + std::to_string(image.height) + ", expected " +
                      std::to_string(width) + " x " + std::to_string(height));
    return image;
}

// The keys of a statistical reference, refused in a deterministic one.
constexpr std::string_view kStatisticalKeys[] = {"samples", "rmse_limit", "worst_correct_rmse", "bias_lsb", "outlier_z"};

StatisticalReference readStats(const TomlReader& r, const fs::path& folder, const std::string& id, const toml::table& t,
                               int w, int h) {
    StatisticalReference s;
    s.samples = int(r.requiredInteger(t, "", "samples", 1, std::numeric_limits<int>::max()));
    s.rmseLimit = r.requiredNumber(t, "", "rmse_limit");
    if (!(s.rmseLimit > 0.)) r.fail(t.get("rmse_limit"), "rmse_limit", "a statistical reference needs rmse_limit > 0");
    s.worstCorrectRmse = r.number(t, "", "worst_correct_rmse").value_or(0.);
    s.biasLsb = r.number(t, "", "bias_lsb").value_or(s.biasLsb);
    s.outlierZ = r.number(t, "", "outlier_z").value_or(s.outlierZ);
    const Image8 whole = readSized(folder / (id + ".mean.png"), w, h);
    const Image8 frac = readSized(folder / (id + ".meanfrac.png"), w, h);
    const Image8 sd = readSized(folder / (id + ".sd.png"), w, h);
    s.mean.resize(whole.rgb.size());
    s.sampleSd.resize(whole.rgb.size());
    for (std::size_t k = 0; k < whole.rgb.size(); ++k) {
        s.mean[k] = float(whole.rgb[k]) + float(frac.rgb[k]) / 256.f;
        s.sampleSd[k] = float(sd.rgb[k]) / kSdScale;
    }
    return s;
}

// `ambiguous = [[i, j], ...]`: pixels of the image.
std::vector<std::pair<int, int>> readAmbiguous(const TomlReader& r, const toml::table& t, const Image8& image) {
    std::vector<std::pair<int, int>> pixels;
    const toml::array* list = r.array(t, "", "ambiguous");
    if (list == nullptr) return pixels;
    for (const toml::node& item : *list) {
        const toml::array* pair = item.as_array();
        if (pair == nullptr || pair->size() != 2) r.fail(&item, "ambiguous", tr("toml.item_pair"));
        pixels.emplace_back(int(r.integerOf(*pair->get(0), "ambiguous", 0, image.width - 1)),
                            int(r.integerOf(*pair->get(1), "ambiguous", 0, image.height - 1)));
    }
    return pixels;
}

FigureReference readReference(const fs::path& folder, const fs::path& file) {
    const toml::table t = parseTomlFile(file);
    const TomlReader r(file);
    r.onlyKeys(t, "", {"lab", "kind", "render_milliseconds", "ambiguous", "samples", "rmse_limit", "worst_correct_rmse", "bias_lsb", "outlier_z"});
    FigureReference f;
    f.id = file.stem().string();
    f.lab = int(r.requiredInteger(t, "", "lab", 1, std::numeric_limits<int>::max()));
    f.image = readImage(folder / (f.id + ".png"));
    f.renderSeconds = double(r.integer(t, "", "render_milliseconds", 0, std::numeric_limits<int>::max()).value_or(0)) / 1000.;
    f.ambiguous = readAmbiguous(r, t, f.image);
    const std::string kind = r.string(t, "", "kind").value_or("deterministic");
    if (kind == "statistical") {
        f.stats = readStats(r, folder, f.id, t, f.image.width, f.image.height);
    } else if (kind == "deterministic") {
        for (std::string_view key : kStatisticalKeys)
            if (const toml::node* node = t.get(key)) r.fail(node, key, tr("toml.only_statistical"));
    } else {
        r.fail(t.get("kind"), "kind", "\"" + kind + "\"; expected deterministic or statistical");
    }
    return f;
}

} // namespace

ReferenceSet loadReferences(const std::vector<fs::path>& folders) {
    ReferenceSet set;
    std::string names;
    for (const fs::path& folder : folders) {
        names += (names.empty() ? "" : ", ") + folder.string();
        std::error_code error;
        if (!fs::is_directory(folder, error)) continue; // a lab with no figure yet
        for (const auto& entry : fs::directory_iterator(folder)) {
            const fs::path file = entry.path();
            if (file.extension() != ".toml" || file.filename() == "mistakes.toml") continue;
            set.figures.push_back(readReference(folder, file));
        }
    }
    std::sort(set.figures.begin(), set.figures.end(),
              [](const auto& a, const auto& b) { return std::tie(a.lab, a.id) < std::tie(b.lab, b.id); });
    if (set.figures.empty()) throw std::runtime_error("no reference in " + names + " (made by `raylab references`)");
    return set;
}

bool writePngIfChanged(const fs::path& path, const Image8& image) {
    std::error_code error;
    if (fs::is_regular_file(path, error)) {
        try {
            const Image8 old = readImage(path);
            if (old.width == image.width && old.height == image.height && old.rgb == image.rgb) return false;
        } catch (const std::exception&) {
            // not a picture we can read: written anew
        }
    }
    writePng(path, image);
    return true;
}

namespace {

// The same for a text file.
void writeFileIfChanged(const fs::path& path, const std::string& text) {
    std::ifstream in(path, std::ios::binary);
    const std::string old{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (!in.bad() && old == text) return;
    writeFileAtomically(path, text);
}

} // namespace

void writeReference(const fs::path& folder, const FigureReference& f) {
    fs::create_directories(folder);
    writePngIfChanged(folder / (f.id + ".png"), f.image);
    toml::table t;
    t.insert("lab", f.lab);
    t.insert("kind", f.stats ? "statistical" : "deterministic");
    // Rounded up to a tenth of a second: a regeneration rarely changes it (the budget's floor is 20 s).
    t.insert("render_milliseconds", std::int64_t(std::ceil(f.renderSeconds * 10.)) * 100);
    toml::array ambiguous;
    for (const auto& [i, j] : f.ambiguous) ambiguous.push_back(toml::array{i, j});
    t.insert("ambiguous", ambiguous);
    if (f.stats) {
        const StatisticalReference& s = *f.stats;
        t.insert("samples", s.samples);
        t.insert("rmse_limit", s.rmseLimit);
        t.insert("worst_correct_rmse", s.worstCorrectRmse);
        t.insert("bias_lsb", s.biasLsb);
        t.insert("outlier_z", s.outlierZ);
        Image8 whole{f.image.width, f.image.height, {}}, frac = whole, sd = whole;
        for (std::size_t k = 0; k < s.mean.size(); ++k) {
            const float m = std::clamp(s.mean[k], 0.f, 255.f);
            const float w = std::floor(m);
            whole.rgb.push_back(std::uint8_t(w));
            frac.rgb.push_back(std::uint8_t(std::min(255.f, std::round((m - w) * 256.f))));
            sd.rgb.push_back(std::uint8_t(std::min(255.f, std::round(s.sampleSd[k] * kSdScale))));
        }
        writePngIfChanged(folder / (f.id + ".mean.png"), whole);
        writePngIfChanged(folder / (f.id + ".meanfrac.png"), frac);
        writePngIfChanged(folder / (f.id + ".sd.png"), sd);
    }
    std::ostringstream out;
    out << "# Made by `raylab references` from solutions/; see docs/grading.md.\n" << t << "\n";
    writeFileIfChanged(folder / (f.id + ".toml"), out.str());
}

} // namespace raylab::grader
