// Built with the untouched stubs of labs/: every figure says which function to write, and where.
#include "support/figures.h"

#include <doctest/doctest.h>

using namespace raylab;
using namespace raylab::test;

TEST_SUITE("stubs") {

TEST_CASE("each lab's stub is reported as not done yet, naming its function and file") {
    struct Expected {
        const char* id;
        const char* message;
    };
    // Lab 2's camera comes first in every ray-traced figure, so it is the first stub they meet.
    for (const Expected& e : {Expected{"lab1_gradient", "lab 1 not done yet: write fillGradient in labs/lab1_first_image/gradient.cpp:"},
                              Expected{"lab2_directions", "lab 2 not done yet: write PerspectiveCamera::updateViewport in labs/lab2_primary_rays/perspective_camera.cpp:"},
                              Expected{"lab5_antialiased", "lab 2 not done yet: write PerspectiveCamera::updateViewport"}}) {
        const FigureResult r = renderScene(figureScene(e.id), RenderOptions{});
        CHECK(r.status == FigureResult::Status::NotDoneYet);
        CHECK_MESSAGE(r.message.rfind(e.message, 0) == 0, r.message);
    }
}

}
