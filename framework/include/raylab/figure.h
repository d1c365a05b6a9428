#pragma once
// Renders a scene description with whichever lab code this program was built with.

#include "raylab/renderer.h"
#include "raylab/scene_file.h"

#include <optional>
#include <string>

namespace raylab {

struct RenderOptions {
    int threads = 0;       // 0: one per core
    bool progress = false; // a progress bar on a terminal
};

struct FigureResult {
    enum class Status {
        Rendered,
        NotDoneYet, // a lab stub was reached: message names the function and where to write it
        Failed,     // anything else the code threw: message says what
    };
    Status status = Status::Failed;
    std::string message;
    std::optional<Texture> image;
    RenderStats stats;
};

// Never throws: a stub or an error in the lab code is reported in the result.
FigureResult renderScene(const SceneDescription& description, const RenderOptions& options);

} // namespace raylab
