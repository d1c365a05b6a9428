// The figure steps the labs register for the crash finder (src/figure_steps.h): each is a function
// its lab's lab.toml declares (a course's lab or a given one, whose reference registers its steps too),
// and they run in the order a ray needs them, labs in order.
#include "support/scene_files.h"
#include "grader/lab_catalog.h"
#include "src/figure_steps.h"
#include "src/scene_file.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <tuple>
#include <vector>

namespace {

using namespace raylab;

grader::LabCatalog labCatalog() { return grader::loadLabCatalog(test::kLabsDir); }

std::vector<std::string> labIds(const grader::LabCatalog& labs) {
    std::vector<std::string> ids;
    for (const grader::LabDescription& lab : labs.labs) ids.push_back(lab.id);
    return ids;
}

std::vector<std::string> g_entered;

} // namespace

TEST_SUITE("figure steps") {
    TEST_CASE("every step is a [[function]] of its own lab's lab.toml") {
        const grader::LabCatalog labs = labCatalog();
        const std::vector<std::string> names = figureSteps().names();
        for (const std::string& name : names) {
            const FigureStep& step = figureSteps().find(name)->value;
            CHECK(step.function == name);
            std::vector<grader::LabDescription> all = labs.labs;
            all.insert(all.end(), labs.given.begin(), labs.given.end());
            const auto lab = std::find_if(all.begin(), all.end(), [&](const grader::LabDescription& l) { return l.id == step.lab; });
            REQUIRE_MESSAGE(lab != all.end(), "the step " << name << " is of no lab: " << step.lab);
            CHECK_MESSAGE(std::any_of(lab->functions.begin(), lab->functions.end(),
                                      [&](const grader::LabFunction& f) { return f.name == name; }),
                          name << " is not a [[function]] of " << lab->file.string());
        }
    }

    TEST_CASE("on every figure the steps run in the order a ray needs them: setup, then each pixel's, labs in order") {
        const grader::LabCatalog labs = labCatalog();
        const std::vector<std::string> ids = labIds(labs);
        // The registered steps in the order figure_steps.h promises: stage, then lab, then registration.
        std::vector<const FigureStep*> steps;
        for (const std::string& name : figureSteps().names()) steps.push_back(&figureSteps().find(name)->value);
        const auto rank = [&](const FigureStep* s) {
            return std::tuple(s->stage, std::find(ids.begin(), ids.end(), s->lab) - ids.begin(), s->sequence);
        };
        std::sort(steps.begin(), steps.end(), [&](const FigureStep* a, const FigureStep* b) { return rank(a) < rank(b); });
        std::vector<std::string> setup, pixel;
        for (const FigureStep* step : steps) (step->stage == FigureStage::Setup ? setup : pixel).push_back(step->function);
        for (SceneDescription d : grader::loadFiguresInLabOrder({}, labs)) {
            CAPTURE(d.id);
            d.width = 2;
            d.height = 1;
            d.samples = 2;
            g_entered.clear();
            runFigureSteps(d, {}, ids, [](const std::string& function) { g_entered.push_back(function); });
            // A whole image (no camera built) has no pixel steps; a figure with rays has them at each pixel.
            std::vector<std::string> expected = setup;
            if (g_entered.size() > setup.size())
                for (int k = 0; k < d.width * d.height; ++k) expected.insert(expected.end(), pixel.begin(), pixel.end());
            CHECK(g_entered == expected);
        }
    }
}
