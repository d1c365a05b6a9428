#include "build_info.h"
#include "commands.h"
#include "figure_process.h"

#include "grader/judge/references.h"
#include "grader/lab_catalog.h"

#include "src/atomic_file.h"
#include "src/contact_sheet.h"
#include "src/figure.h"
#include "raylab/image_io.h"
#include "src/messages.h"
#include "src/terminal.h"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace raylab::cli {

namespace {

// Writes a PNG; a file that cannot be written is a failed figure, with the reason on its line. A
// handout's picture whose pixels did not change is left as it is, byte for byte (another zlib may
// deflate the same pixels otherwise: the repository would show a change where there is none).
bool writeFigure(const std::string& id, const std::filesystem::path& file, const Image8& image, bool keepSamePixels = false) {
    try {
        if (keepSamePixels) grader::writePngIfChanged(file, image);
        else writePng(file, image);
        return true;
    } catch (const WriteError& e) {
        std::printf("  %-24s FAILED  %s\n", id.c_str(), e.what());
        return false;
    }
}

// The lab, as "6", that stands in this program as its stub because its code does not compile, and
// that kept figure `d` from being drawn: its own lab, else the lab of the stub it stopped in; "" if none.
std::string brokenLabOf(const SceneDescription& d, const NotDoneYet& todo, const grader::LabCatalog& labs) {
    if (const int own = labs.labNumberOfFigure(d.id); own != 0 && build::labOrigin(own) == "stubs") return std::to_string(own);
    if (std::filesystem::path(todo.file()).generic_string().find("framework/stubs/") == std::string::npos) return "";
    const std::string& lab = todo.lab(); // "lab 6"
    const std::size_t digit = lab.find_first_of("0123456789");
    return digit == std::string::npos ? lab : lab.substr(digit);
}

// Writes the figure's PNG and prints its line; returns false when the figure is not usable.
bool report(const SceneDescription& d, const FigureResult& r, const std::filesystem::path& file, const grader::LabCatalog& labs,
            bool keepSamePixels = false) {
    switch (r.status) {
    case FigureResult::Status::NotDoneYet:
        // A stub of framework/stubs/ stands for a lab whose code does not compile (fresh_build.cpp):
        // the figure's own lab, or the lab it stopped in.
        if (const std::string broken = brokenLabOf(d, *r.todo, labs); !broken.empty()) {
            std::printf("  %-24s %s\n", d.id.c_str(),
                        tr("figures.does_not_compile", {{"lab", broken}, {"log", lastBuildProblemFile().string()}}).c_str());
            return false;
        }
        std::printf("  %-24s %s\n", d.id.c_str(), tr("figures.todo", {{"message", grader::waitingMessage(labs, d.id, *r.todo)}}).c_str());
        return true;
    case FigureResult::Status::Failed:
        std::printf("  %-24s %s\n", d.id.c_str(), tr("figures.failed", {{"message", r.message}}).c_str());
        return false;
    case FigureResult::Status::Rendered: break;
    }
    std::uint64_t nonFinite = 0;
    if (!writeFigure(d.id, file, quantize(*r.image, &nonFinite), keepSamePixels)) return false;
    std::string speed;
    if (!isRegisteredImage(d.shading) && r.stats.seconds > 0.)
        speed = tr("figures.speed", {{"mrays", formatFixed(double(r.stats.primaryRays) / r.stats.seconds * 1e-6, 1)}});
    std::printf("  %-24s %s\n", d.id.c_str(),
                tr("figures.rendered", {{"seconds", formatFixed(r.stats.seconds, 3)}, {"speed", speed}, {"file", file.string()}})
                    .c_str());
    if (nonFinite > 0) {
        std::printf("  %-24s %s\n", d.id.c_str(), tr("figures.nan", {{"count", std::to_string(nonFinite)}}).c_str());
        return false;
    }
    return true;
}

struct FiguresOptions {
    std::filesystem::path scenes;  // folder of figure scene files
    std::filesystem::path out;     // where DIR/<id>.png go
    bool handouts = false;         // instead, each figure beside its lab's handout: labs/<lab>/figures/<id>.png
    std::vector<std::string> only; // figure ids; empty: all
    int lab = 0;                   // only this lab's figures; 0: all
    int threads = 0;
};

// Where figure `id` is written: DIR/<id>.png, or with --handouts beside its lab's handout (the
// handouts show labs/<lab>/figures/<id>.png: a lab's pictures live in its own folder).
std::filesystem::path figureFile(const FiguresOptions& o, const std::string& id, const grader::LabCatalog& labs) {
    if (!o.handouts) return o.out / (id + ".png");
    const grader::LabDescription* lab = labs.labOfFigure(id);
    if (lab == nullptr) throw std::invalid_argument(tr("figures.no_handout", {{"id", id}}));
    const std::filesystem::path folder = labsFolder() / lab->id / "figures";
    std::filesystem::create_directories(folder);
    return folder / (id + ".png");
}

// Renders figures, a line each. 1 if a figure failed or has NaN pixels, else 0: a figure waiting
// for a lab not done yet is reported, not a failure.
int runFigures(const FiguresOptions& o) {
    const grader::LabCatalog labs = courseLabs();
    if (o.lab != 0 && labs.lab(o.lab) == nullptr)
        throw std::invalid_argument(tr("figures.no_such_lab", {{"lab", std::to_string(o.lab)}, {"labs", labList(labs)}}));
    std::vector<SceneDescription> scenes = grader::loadFiguresInLabOrder(o.scenes, labs);
    for (const std::string& id : o.only)
        if (std::none_of(scenes.begin(), scenes.end(), [&](const auto& d) { return d.id == id; })) {
            std::string known;
            for (const auto& d : scenes) known += " " + d.id;
            throw std::invalid_argument(tr("figures.unknown", {{"id", id}, {"folder", (o.scenes.empty() ? labsFolder() / "*" / "scenes" : o.scenes).string()}, {"known", known}}));
        }
    std::erase_if(scenes, [&](const SceneDescription& d) {
        const bool wanted = o.only.empty() || std::find(o.only.begin(), o.only.end(), d.id) != o.only.end();
        return !wanted || (o.lab != 0 && labs.labNumberOfFigure(d.id) != o.lab);
    });

    const std::string folder = o.handouts ? (labsFolder() / "<lab>" / "figures").string() : o.out.string();
    std::printf("%s\n", tr("figures.header", {{"impl", tr(std::string("figures.impl_") + build::kImpl)}, {"origins", build::kLabOrigins}, {"folder", folder}})
                             .c_str());
    int failed = 0, todo = 0;
    const RenderOptions renderOptions{o.threads, stderrIsInteractive()};
    std::vector<ContactSheetItem> sheet;
    for (const SceneDescription& d : scenes) {
        const FigureResult r = renderFigure(d, renderOptions, labs);
        const bool usable = report(d, r, figureFile(o, d.id, labs), labs, o.handouts);
        const bool waiting = usable && r.status == FigureResult::Status::NotDoneYet;
        if (!usable) ++failed;
        if (waiting) ++todo;
        if (r.status == FigureResult::Status::Rendered) sheet.push_back({d.id, quantize(*r.image), ""});
        else sheet.push_back({d.id, std::nullopt, waiting ? "todo" : "failed"});
    }
    // Every figure at a glance, when all of them were asked for (`raylab figures` without --only).
    bool sheetWritten = true;
    if (o.lab == 0 && o.only.empty() && !o.handouts && !sheet.empty()) {
        sheetWritten = writeFigure("contact_sheet", o.out / "contact_sheet.png", makeContactSheet(sheet));
        if (sheetWritten)
            std::printf("  %-24s %s\n", "contact_sheet",
                        tr("figures.written", {{"file", (o.out / "contact_sheet.png").string()}}).c_str());
    }
    std::printf("%s\n", tr("figures.summary", {{"count", std::to_string(scenes.size())},
                                               {"rendered", std::to_string(scenes.size() - std::size_t(todo + failed))},
                                               {"todo", std::to_string(todo)},
                                               {"failed", std::to_string(failed)}})
                            .c_str());
    return failed == 0 && sheetWritten ? 0 : 1;
}

// Renders one scene file to a PNG.
int runRender(const std::filesystem::path& scene, std::filesystem::path out, int threads) {
    const SceneDescription d = loadSceneFile(scene);
    if (out.empty()) out = std::filesystem::path("out") / (d.id + ".png");
    std::printf("%s\n", tr("figures.render_header", {{"scene", scene.string()}, {"width", std::to_string(d.width)},
                                                   {"height", std::to_string(d.height)}, {"picture", d.shading},
                                                   {"samples", std::to_string(d.samples)}, {"sampler", std::string(samplerName(d.sampler))}})
                            .c_str());
    const grader::LabCatalog labs = courseLabs();
    const FigureResult r = renderFigure(d, RenderOptions{threads, stderrIsInteractive()}, labs);
    return report(d, r, out, labs) && r.status == FigureResult::Status::Rendered ? 0 : 1;
}

// The student's figures come from the lab files as they are now: a build older than one of them is
// brought up to date first. False when it could not be.
bool codeIsFresh(Context& context) {
    const std::string self = thisProgram();
    const FreshBuild fresh = ensureFreshBuild(context, {self}, BuildInputs::StudentLabs);
    if (fresh == FreshBuild::BuildFailed || fresh == FreshBuild::Stale) context.exitStatus = 1;
    return context.exitStatus == 0;
}

} // namespace

void addFigureCommands(CLI::App& app, Context& context) {
    auto options = std::make_shared<FiguresOptions>();
    auto renderFigures = [&context, options] {
        if (context.ranInOtherImpl()) return;
        // The handouts show the reference's pictures: a student's build never writes there.
        if (options->handouts && std::string_view(build::kImpl) != "reference")
            throw std::invalid_argument(tr("figures.handouts_reference"));
        if (!codeIsFresh(context)) return;
        options->scenes = context.scenes;
        options->threads = context.threads;
        if (options->out.empty()) options->out = std::filesystem::path("out") / context.impl;
        context.exitStatus = runFigures(*options);
    };

    CLI::App* figures = app.add_subcommand("figures", tr("cli.figures"));
    context.addImplOption(figures);
    figures->add_option("--out", options->out, tr("cli.figures_out"));
    figures->add_option("--only", options->only, tr("cli.figures_only"));
    figures->add_flag("--handouts", options->handouts, tr("cli.figures_handouts"))->excludes("--out");
    context.addRenderOptions(figures);
    figures->callback(renderFigures);

    CLI::App* lab = app.add_subcommand("lab", tr("cli.lab"));
    lab->add_option("N", options->lab, tr("cli.lab_number"))->required()->check(CLI::PositiveNumber);
    lab->add_option("--out", options->out, tr("cli.lab_out"));
    context.addRenderOptions(lab);
    lab->callback(renderFigures);

    auto scene = std::make_shared<std::string>();
    auto out = std::make_shared<std::string>();
    CLI::App* render = app.add_subcommand("render", tr("cli.render"));
    render->add_option(tr("cli.type.FILE"), *scene, tr("cli.render_file"))->required();
    render->add_option("--out", *out, tr("cli.render_out"));
    context.addImplOption(render);
    context.addRenderOptions(render);
    render->callback([&context, scene, out] {
        if (!context.ranInOtherImpl() && codeIsFresh(context)) context.exitStatus = runRender(*scene, *out, context.threads);
    });

    app.add_subcommand("scene-format", tr("cli.scene_format"))->callback([] { std::fputs(sceneTablesReference().c_str(), stdout); });
}

} // namespace raylab::cli
