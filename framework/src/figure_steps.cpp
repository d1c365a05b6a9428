#include "src/figure_steps.h"

#include <algorithm>
#include <iterator>
#include <utility>

namespace raylab {

namespace {

// Built on first use: the labs' steps register during static initialisation, in any order of files.
NameRegistry<FigureStep>& steps() {
    static NameRegistry<FigureStep> registry("figure step");
    return registry;
}

// One stage's steps in the order they run: by their lab's place in `labs`, then as registered.
std::vector<const FigureStep*> stageSteps(FigureStage stage, const std::vector<std::string>& labs) {
    std::vector<const FigureStep*> ordered;
    for (const std::string& name : steps().names()) {
        const FigureStep& step = steps().find(name)->value;
        if (step.stage == stage) ordered.push_back(&step);
    }
    const auto rank = [&](const FigureStep* s) {
        return std::make_pair(std::distance(labs.begin(), std::find(labs.begin(), labs.end(), s->lab)), s->sequence);
    };
    std::sort(ordered.begin(), ordered.end(), [&](const FigureStep* a, const FigureStep* b) { return rank(a) < rank(b); });
    return ordered;
}

} // namespace

void registerFigureStep(const std::string& lab, const std::string& function, FigureStage stage,
                        void (*call)(FigureStepContext&), SourcePlace where) {
    static int registered = 0; // static initialisation runs in order within a file
    steps().add(function, {function, lab, stage, call, registered++}, where);
}

const NameRegistry<FigureStep>& figureSteps() { return steps(); }

void runFigureSteps(const SceneDescription& d, const RenderOptions& options, const std::vector<std::string>& labs,
                    void (*entering)(const std::string& function)) {
    FigureStepContext context{d, options, std::nullopt, 0, 0, {}};
    for (const FigureStep* step : stageSteps(FigureStage::Setup, labs)) {
        entering(step->function);
        step->call(context);
    }
    if (!context.render) return;
    const std::vector<const FigureStep*> pixelSteps = stageSteps(FigureStage::Pixel, labs);
    for (context.j = 0; context.j < context.render->camera().height(); ++context.j)
        for (context.i = 0; context.i < context.render->camera().width(); ++context.i)
            for (const FigureStep* step : pixelSteps) {
                entering(step->function);
                step->call(context);
            }
}

} // namespace raylab
