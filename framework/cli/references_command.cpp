// raylab references: renders the graded figures from solutions/ into each lab's grading folder
// (framework/grader/labs/<lab>/references/, or one --out folder), with the data the image checks need
// (docs/grading.md), and the mistakes' signatures.
#include "build_info.h"
#include "commands.h"

#include "grader/judge/compare.h"
#include "grader/judge/diagnosis.h"
#include "grader/lab_catalog.h"
#include "grader/judge/reference_render.h"
#include "grader/judge/references.h"
#include "grader/judge/grade.h"
#include "src/messages.h"

#include <cstdio>
#include <memory>
#include <set>
#include <stdexcept>

namespace raylab::cli {

namespace {

namespace fs = std::filesystem;
using namespace raylab::grader;

// Each mistake's agent renders the figures of `scenes`; those that fail their check are its signatures,
// kept small. Only the figures rendered are touched: a signature of a figure not in `scenes` stays, one
// whose figure now passes is removed, and an unchanged picture is left byte for byte.
void makeSignatures(const std::vector<fs::path>& folders, const fs::path& bin, const fs::path& scenes, const LabCatalog& labs) {
    const ReferenceSet references = loadReferences(folders);
    const std::vector<Mistake> mistakes = loadMistakes(folders);
    for (const Mistake& m : mistakes) {
        const fs::path agent = bin / ("raylab-mistake-" + m.id);
        if (!fs::exists(agent)) {
            std::printf("  %-28s skipped: no %s (build the tests first)\n", m.id.c_str(), agent.string().c_str());
            continue;
        }
        GradeSetup setup;
        setup.references = references;
        setup.labs = labs;
        setup.scenes = scenes;
        setup.scratch = fs::temp_directory_path() / ("raylab-signature-" + m.id);
        fs::remove_all(setup.scratch);
        const std::map<std::string, Image8> pictures = renderFigures(setup, agent);
        std::string kept, removed;
        std::set<fs::path> touched;
        for (const FigureReference& r : references.figures) {
            const auto picture = pictures.find(r.id);
            if (picture == pictures.end()) continue;
            const fs::path out = signatureFolder(folders, r.id, m.id); // with the figure, not the mistake
            const fs::path file = out / (r.id + ".png");
            touched.insert(out);
            if (compareImage(r, picture->second).passed) {
                if (fs::remove(file)) removed += " " + r.id;
                continue;
            }
            fs::create_directories(out);
            writePngIfChanged(file, downsample(picture->second));
            kept += " " + r.id;
        }
        std::error_code error;
        for (const fs::path& out : touched)
            if (fs::is_empty(out, error)) fs::remove(out, error);
        std::printf("  %-28s signatures:%s%s%s\n", m.id.c_str(), kept.empty() ? " none among the figures rendered" : kept.c_str(),
                    removed.empty() ? "" : "; removed (the figure now passes):", removed.c_str());
        fs::remove_all(setup.scratch);
    }
}

void printReference(const SceneDescription& d, const RenderedReference& rendered) {
    const FigureReference& f = rendered.reference;
    if (!f.stats) {
        std::printf("  %-24s deterministic: %zu ambiguous pixels\n", d.id.c_str(), f.ambiguous.size());
        return;
    }
    const StatisticalMargins& m = rendered.margins;
    std::printf("  %-24s 20 seeds: worst |mean signed difference| %.4f LSB (allowed %.4f), worst outliers %.0f\n",
                d.id.c_str(), m.worstBias, m.biasLimit, m.worstOutliers);
    std::printf("  %-24s statistical: worst RMSE of 20 correct renders %.3f LSB, limit %.3f\n", d.id.c_str(),
                f.stats->worstCorrectRmse, f.stats->rmseLimit);
}

// `out`: one folder for every figure; empty: each lab's references/.
int makeReferences(const std::string& out, const fs::path& scenes, const std::string& mistakesBin, int threads) {
    const LabCatalog labs = courseLabs();
    std::printf("raylab references: %s -> %s\n", build::kLabOrigins,
                out.empty() ? (fs::path("framework/grader/labs/<lab>/references")).string().c_str() : out.c_str());
    for (const SceneDescription& d : loadFiguresInLabOrder(scenes, labs)) {
        const LabDescription* lab = labs.labOfFigure(d.id);
        if (lab == nullptr) throw std::runtime_error(d.file.string() + ": no lab lists this figure (labs/*/lab.toml, [[figure]])");
        const RenderedReference rendered = renderReference(d, lab->number, threads);
        printReference(d, rendered);
        const fs::path folder = out.empty() ? referencesFolder(*lab) : fs::path(out);
        fs::create_directories(folder);
        writeReference(folder, rendered.reference);
    }
    if (!mistakesBin.empty()) makeSignatures(referenceFolders(out), mistakesBin, scenes, labs);
    return 0;
}

} // namespace

void addReferencesCommand(CLI::App& app, Context& context) {
    auto out = std::make_shared<std::string>();
    auto mistakes = std::make_shared<std::string>();
    CLI::App* references = app.add_subcommand("references", tr("cli.references"));
    references->add_option("--out", *out, tr("cli.grade_references"));
    references->add_option("--mistakes", *mistakes,
                           tr("cli.references_mistakes"));
    context.addRenderOptions(references);
    references->callback([&context, out, mistakes] {
        context.impl = "reference";
        if (context.ranInOtherImpl()) return;
        context.exitStatus = makeReferences(*out, context.scenes, *mistakes, context.threads);
    });
}

} // namespace raylab::cli
