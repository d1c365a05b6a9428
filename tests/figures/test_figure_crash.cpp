// A lab function that crashes costs its figure only, and the figure's message names the function
// (cli/figure_process.cpp): here lab 3's SphereGeometry::intersect (crashing_sphere.cpp), found by
// the steps lab 3's grading folder registers; the other labs are the reference's.
#include "support/scene_files.h"
#include "cli/figure_process.h"
#include "src/messages.h"

#include <doctest/doctest.h>

#include <csignal>
#include <filesystem>

namespace {

using namespace raylab;


grader::LabCatalog labCatalog() { return grader::loadLabCatalog(test::kLabsDir); }

#if defined(__unix__) || defined(__APPLE__)
// doctest's own crash handler, which the figure's child would inherit and report as this test's
// crash, set aside while the figure is drawn: the child dies of its signal as in raylab.
struct DefaultCrashHandler {
    void (*previous)(int) = std::signal(SIGSEGV, SIG_DFL);
    ~DefaultCrashHandler() { std::signal(SIGSEGV, previous); }
    DefaultCrashHandler() = default;
    DefaultCrashHandler(const DefaultCrashHandler&) = delete;
    DefaultCrashHandler& operator=(const DefaultCrashHandler&) = delete;
};
#endif

} // namespace

TEST_SUITE("figure crash") {
#if defined(__unix__) || defined(__APPLE__) // elsewhere a figure is drawn in the command's own process
    TEST_CASE("a crash in lab 3's intersect names lab 3 and SphereGeometry::intersect") {
        setLanguage(Language::En);
        SceneDescription d = loadSceneFile(test::figureSceneFile("lab3_flat"));
        d.width = 8;
        d.height = 6;
        const DefaultCrashHandler handler;
        const FigureResult r = cli::renderFigure(d, {1, false}, labCatalog());
        CHECK(r.status == FigureResult::Status::Failed);
        CHECK(r.message == "lab 3: SphereGeometry::intersect in labs/lab3_sphere/ crashed (segmentation fault: a bad "
                           "pointer or index?)");
    }

    TEST_CASE("a figure that meets no sphere is drawn") {
        const FigureResult r = cli::renderFigure(loadSceneFile(test::figureSceneFile("lab2_directions")), {1, false}, labCatalog());
        CHECK(r.status == FigureResult::Status::Rendered);
        CHECK(r.image.has_value());
    }
#endif
}
