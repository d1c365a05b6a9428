#include "grader/judge/references.h"

#include "src/atomic_file.h"

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
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

StatisticalReference readStats(const fs::path& folder, const std::string& id, const toml::table& t, int w, int h) {
    const fs::path meta = folder / (id + ".toml");
    StatisticalReference s;
    s.samples = t["samples"].value_or(0);
    s.rmseLimit = t["rmse_limit"].value_or(0.);
    s.worstCorrectRmse = t["worst_correct_rmse"].value_or(0.);
    s.biasLsb = t["bias_lsb"].value_or(0.05);
    s.outlierZ = t["outlier_z"].value_or(6.);
    if (s.samples < 1 || !(s.rmseLimit > 0.)) bad(meta, "a statistical reference needs samples >= 1 and rmse_limit > 0");
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

} // namespace

ReferenceSet loadReferences(const fs::path& folder) {
    ReferenceSet set;
    set.folder = folder;
    std::error_code error;
    if (!fs::is_directory(folder, error))
        throw std::runtime_error("no reference folder " + folder.string() + " (made by `raylab references`)");
    for (const auto& entry : fs::directory_iterator(folder)) {
        const fs::path file = entry.path();
        if (file.extension() != ".toml" || file.filename() == "mistakes.toml") continue;
        toml::table t;
        try {
            t = toml::parse_file(file.string());
        } catch (const toml::parse_error& e) {
            bad(file, std::string(e.description()));
        }
        FigureReference f;
        f.id = file.stem().string();
        f.lab = t["lab"].value_or(0);
        f.image = readImage(folder / (f.id + ".png"));
        if (const toml::array* list = t["ambiguous"].as_array())
            for (const toml::node& n : *list) {
                const toml::array* p = n.as_array();
                if (!p || p->size() != 2) bad(file, "ambiguous: each entry is [i, j]");
                f.ambiguous.emplace_back((*p)[0].value_or(-1), (*p)[1].value_or(-1));
            }
        const std::string kind = t["kind"].value_or(std::string("deterministic"));
        if (kind == "statistical") f.stats = readStats(folder, f.id, t, f.image.width, f.image.height);
        else if (kind != "deterministic") bad(file, "kind = \"" + kind + "\"; expected deterministic or statistical");
        set.figures.push_back(std::move(f));
    }
    std::sort(set.figures.begin(), set.figures.end(),
              [](const auto& a, const auto& b) { return std::tie(a.lab, a.id) < std::tie(b.lab, b.id); });
    if (set.figures.empty()) throw std::runtime_error("no reference in " + folder.string() + " (made by `raylab references`)");
    return set;
}

void writeReference(const fs::path& folder, const FigureReference& f) {
    fs::create_directories(folder);
    writePng(folder / (f.id + ".png"), f.image);
    toml::table t;
    t.insert("lab", f.lab);
    t.insert("kind", f.stats ? "statistical" : "deterministic");
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
        writePng(folder / (f.id + ".mean.png"), whole);
        writePng(folder / (f.id + ".meanfrac.png"), frac);
        writePng(folder / (f.id + ".sd.png"), sd);
    }
    std::ostringstream out;
    out << "# Made by `raylab references` from solutions/; see docs/grading.md.\n" << t << "\n";
    writeFileAtomically(folder / (f.id + ".toml"), out.str());
}

} // namespace raylab::grader
