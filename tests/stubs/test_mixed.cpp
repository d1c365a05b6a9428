// Built with lab 3 and lab 5 from labs/ (stubs) and the other labs from solutions/: the labs that do
// not need the stubs keep working, the others name the stub they are waiting for (lab 5's, where the
// course hands lab 5 out).
#include "support/course.h"
#include "support/figures.h"

#include <doctest/doctest.h>

using namespace raylab;
using namespace raylab::test;

TEST_SUITE("stubs") {

TEST_CASE("a lab not done yet stops only the figures that need it") {
    CHECK(renderScene(figureScene("lab1_gradient"), {}).status == FigureResult::Status::Rendered);
    CHECK(renderScene(figureScene("lab2_directions"), {}).status == FigureResult::Status::Rendered);
    for (const char* id : {"lab3_flat", "lab3_cosine", "lab4_a"}) {
        const FigureResult r = renderScene(figureScene(id), {});
        CHECK(r.status == FigureResult::Status::NotDoneYet);
        CHECK_MESSAGE(r.message.rfind("lab 3 not done yet: write RayCastIntegrator::Li in labs/lab3_sphere/ray_cast_integrator.cpp:", 0) == 0,
                      r.message);
    }
}

}

TEST_SUITE("stubs: lab 5") { // a given lab 5 is its reference

TEST_CASE("lab 5 not done yet stops its figure at its own stub") {
    if (!labInCourse(RAYLAB_LABS_DIR, 5)) return;
    const FigureResult r = renderScene(figureScene("lab5_antialiased"), {});
    CHECK(r.status == FigureResult::Status::NotDoneYet);
    CHECK(r.message.rfind("lab 5 not done yet: write Renderer::setNbPixelSamples", 0) == 0);
}

}
