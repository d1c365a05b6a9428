#pragma once
// A figure's lab functions as steps the crash finder can call one at a time (cli/figure_process.cpp):
// when a figure's child crashed, a second child runs the steps on the figure's own rays, each under
// its function's name, and the name it was in when it crashed is the function to blame. Each lab's
// grading folder registers its own (framework/grader/labs/<lab>/figure_steps.cpp), by the name its
// lab.toml gives the function; the framework knows no lab. A lab function with no step is simply not
// searched.
//
//   RAYLAB_REGISTER_FIGURE_STEP("SphereGeometry::intersect", FigureStage::Pixel, intersections);
//
// The lab is the grading folder's (RAYLAB_LAB_ID, its folder's name, which CMake defines for it).

#include "src/figure.h"
#include "src/name_registry.h"

#include <optional>
#include <string>
#include <vector>

namespace raylab {

// What the steps share, from the first to the last.
struct FigureStepContext {
    const SceneDescription& description;
    const RenderOptions& options;
    std::optional<SceneRender> render; // built by a setup step (the camera's); no pixel step runs without it
    int i = 0, j = 0;                  // the pixel the pixel steps are at
    Ray ray;                           // its centre's ray, from the pixel step that makes it (the camera's)
};

enum class FigureStage {
    Setup, // once a figure, in the order of the labs: a whole image, or the camera (building `render`)
    Pixel, // at each pixel, in the order of the labs: the ray first, then what the ray meets
};

struct FigureStep {
    std::string function; // as the lab's lab.toml names it
    std::string lab;      // the lab's id, its folder's name
    FigureStage stage;
    void (*call)(FigureStepContext& context); // does nothing when the figure does not need the function
    int sequence = 0;                         // a lab's steps run in the order they are registered
};

// Adds the step that calls `function` of lab `lab`; a function registered twice is a std::logic_error
// naming both places. A lab registers its steps in one file, in the order a ray needs them.
void registerFigureStep(const std::string& lab, const std::string& function, FigureStage stage,
                        void (*call)(FigureStepContext&), SourcePlace where);

// The registered steps, by function name.
const NameRegistry<FigureStep>& figureSteps();

// Runs every step on the figure `d`, the setup steps then the pixel steps at each pixel centre, each
// stage's steps in the order of `labs` (lab ids; a step of another lab comes last), then of their
// registration; `entering(function)` is told each step's name before its call (a string that lives as
// long as the program). Throws whatever the lab code throws.
void runFigureSteps(const SceneDescription& d, const RenderOptions& options, const std::vector<std::string>& labs,
                    void (*entering)(const std::string& function));

struct FigureStepRegistrar {
    FigureStepRegistrar(const std::string& lab, const std::string& function, FigureStage stage,
                        void (*call)(FigureStepContext&), SourcePlace where = SourcePlace::here()) {
        registerFigureStep(lab, function, stage, call, where);
    }
};

} // namespace raylab

// At namespace scope in a lab's figure_steps.cpp.
#define RAYLAB_REGISTER_FIGURE_STEP(function, stage, call)                                                             \
    RAYLAB_REGISTRAR(::raylab::FigureStepRegistrar)(RAYLAB_LAB_ID, (function), (stage), (call))
