// The figure steps the labs register for the crash finder (src/figure_steps.h): each is a function
// its lab's lab.toml declares, and they run in the order a ray needs them, labs in order.
#include "support/scene_files.h"
#include "grader/lab_catalog.h"
#include "src/figure_steps.h"
#include "src/scene_file.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <string>
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
        CHECK(names.size() == 8);
        for (const std::string& name : names) {
            const FigureStep& step = figureSteps().find(name)->value;
            CHECK(step.function == name);
            const auto lab = std::find_if(labs.labs.begin(), labs.labs.end(),
                                          [&](const grader::LabDescription& l) { return l.id == step.lab; });
            REQUIRE_MESSAGE(lab != labs.labs.end(), "the step " << name << " is of no lab: " << step.lab);
            CHECK_MESSAGE(std::any_of(lab->functions.begin(), lab->functions.end(),
                                      [&](const grader::LabFunction& f) { return f.name == name; }),
                          name << " is not a [[function]] of " << lab->file.string());
        }
    }

    TEST_CASE("the steps run in the order a ray needs them: setup, then each pixel's, labs in order") {
        SceneDescription d = loadSceneFile(test::figureSceneFile("lab5_antialiased"));
        d.width = 2;
        d.height = 1;
        d.samples = 2;
        g_entered.clear();
        runFigureSteps(d, {}, labIds(labCatalog()), [](const std::string& function) { g_entered.push_back(function); });
        const std::vector<std::string> setup = {
            "fillGradient", "PerspectiveCamera::updateViewport",
            "the lookAt constructor PerspectiveCamera(width, height, position, target, up, fovy)"};
        const std::vector<std::string> pixel = {"PerspectiveCamera::generateRay", "SphereGeometry::intersect",
                                                "SphereGeometry::computeNormal", "RayCastIntegrator::Li",
                                                "Renderer::renderPixel"};
        std::vector<std::string> expected = setup;
        for (int k = 0; k < d.width * d.height; ++k) expected.insert(expected.end(), pixel.begin(), pixel.end());
        CHECK(g_entered == expected);
    }

    TEST_CASE("a whole image has no pixel steps") {
        const SceneDescription d = loadSceneFile(test::figureSceneFile("lab1_gradient"));
        g_entered.clear();
        runFigureSteps(d, {}, labIds(labCatalog()), [](const std::string& function) { g_entered.push_back(function); });
        CHECK(g_entered.size() == 3); // the setup steps, the gradient drawn by the first
        CHECK(g_entered.front() == "fillGradient");
    }
}
