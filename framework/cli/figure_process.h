#pragma once
// Drawing a figure so that a lab function that crashes costs that figure only (figure_process.cpp).

#include "grader/lab_catalog.h"
#include "src/figure.h"

namespace raylab::cli {

// renderScene, in a child process where there are processes to have: a crash in the lab code is a
// Failed result whose message names the lab function it happened in, when one of `labs` can be found.
FigureResult renderFigure(const SceneDescription& description, const RenderOptions& options, const grader::LabCatalog& labs);

} // namespace raylab::cli
