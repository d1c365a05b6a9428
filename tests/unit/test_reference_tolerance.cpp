// The deterministic references' tolerance to rounding (docs/grading.md, "Deterministic figures"): a
// shadow ray leaving a point a few float spacings off its surface, as a correct camera or
// intersection of the student's own puts it, never fails a figure; the probe that finds the pixels
// where it would moves the point, and only while it is set.
#include "support/figures.h"

#include "grader/judge/compare.h"
#include "grader/judge/references.h"
#include "raylab/scene.h"
#include "src/figure.h"
#include "src/shadow_rays.h"

#include <doctest/doctest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <string>

using namespace raylab;
using namespace raylab::test;

namespace {

// The float spacings off their surfaces that reference_render.cpp's probe moves shadow rays' points by.
constexpr float kProbeUlps = 4.f;

// Sets the offset of this thread's shadow rays for one scope.
struct Offset {
    explicit Offset(float ulps) { setShadowOriginOffsetOnThisThread(ulps); }
    ~Offset() { setShadowOriginOffsetOnThisThread(0.f); }
};

// The figure drawn on this thread, ray by ray at the pixels' centres as its reference is, with the
// shadow rays' points moved `ulps` float spacings off their surfaces.
Image8 renderWithOffset(const SceneDescription& d, float ulps) {
    const SceneRender render(d);
    const Offset offset(ulps);
    Image8 image{d.width, d.height, {}};
    image.rgb.reserve(std::size_t(d.width) * d.height * 3);
    for (int j = 0; j < d.height; ++j)
        for (int i = 0; i < d.width; ++i) {
            const Ray ray = render.camera().generateRay((float(i) + 0.5f) / float(d.width), (float(j) + 0.5f) / float(d.height));
            const Color c = render.integrator().Li(render.scene(), ray);
            for (int k = 0; k < 3; ++k) image.rgb.push_back(toByte(c[k]));
        }
    return image;
}

grader::FigureReference lab6Reference(const std::string& id) {
    const grader::ReferenceSet set = grader::loadReferences({kLabsDir.parent_path() / "framework/grader/labs/lab6_shadows/references"});
    const grader::FigureReference* f = set.find(id);
    REQUIRE_MESSAGE(f != nullptr, "no reference " << id);
    return *f;
}

} // namespace

TEST_SUITE("reference tolerance") {

TEST_CASE("a shadow ray that grazes the surface it leaves meets it only from a point moved under it") {
    Scene scene = makeTp1Scene(); // the unit sphere at (0, 0, 3)
    const glm::vec3 p(1.f, 0.f, 3.f); // on the sphere, its normal (1, 0, 0)
    const float c = 2e-3f;             // the cosine between the shadow ray and the normal: a grazing ray
    const Ray grazing{p, glm::normalize(glm::vec3(c, 0.f, 1.f))};
    // 4 spacings of 3 (2.4e-7 each) under the surface, the ray leaves the sphere at about
    // 9.5e-7 / 2e-3 = 4.8e-4, past tMin = 1e-4: the point shadows itself.
    CHECK_FALSE(scene.occluded(grazing, 1e-4f, 10.f));
    {
        const Offset under(-kProbeUlps);
        CHECK(scene.occluded(grazing, 1e-4f, 10.f));
    }
    {
        const Offset over(kProbeUlps);
        CHECK_FALSE(scene.occluded(grazing, 1e-4f, 10.f));
    }
    CHECK_FALSE(scene.occluded(grazing, 1e-4f, 10.f)); // the offset ended with its scope
    // One spacing under: 2.4e-7 / 2e-3 = 1.2e-4, just past tMin; a ray less grazing (cosine 0.1)
    // leaves the sphere at 2.4e-6 even from 4 spacings under: tMin = 1e-4 keeps its light.
    {
        const Offset under(-kProbeUlps);
        CHECK_FALSE(scene.occluded(Ray{p, glm::normalize(glm::vec3(0.1f, 0.f, 1.f))}, 1e-4f, 10.f));
    }
    // On the ground plane y = -1 under a light: the plane's normal, not the sphere's, moves the point.
    scene.add(Plane(glm::vec3(0.f, -1.f, 0.f), glm::vec3(0.f, 1.f, 0.f), Color(0.5f)));
    const Ray alongGround{{5.f, -1.f, 3.f}, glm::normalize(glm::vec3(1.f, c, 0.f))};
    CHECK_FALSE(scene.occluded(alongGround, 1e-4f, 10.f));
    const Offset under(-kProbeUlps);
    CHECK(scene.occluded(alongGround, 1e-4f, 10.f));
}

TEST_CASE("lab 6's figures pass with every shadow ray's point up to 4 spacings off its surface, either side") {
    for (const char* id : {"lab6_no_shadows", "lab6_shadows", "lab6_light_below"}) {
        CAPTURE(std::string(id));
        const grader::FigureReference reference = lab6Reference(id);
        const SceneDescription d = figureScene(id);
        const grader::ImageVerdict asDrawn = grader::compareDeterministic(reference, renderWithOffset(d, 0.f));
        REQUIRE_MESSAGE(asDrawn.passed, asDrawn.reason); // this loop draws the reference's picture
        for (const float ulps : {-4.f, -3.f, -2.f, -1.f, 1.f, 2.f, 3.f, 4.f}) {
            CAPTURE(ulps);
            const grader::ImageVerdict v = grader::compareDeterministic(reference, renderWithOffset(d, ulps));
            CHECK_MESSAGE(v.passed, v.reason);
        }
    }
}

TEST_CASE("8 spacings under the surface is shadow acne that lab6_light_below does not excuse") {
    // Beyond the probe's offsets the tolerance ends: the terminator of the large sphere shadows itself
    // on more pixels than the reference lists.
    const grader::FigureReference reference = lab6Reference("lab6_light_below");
    const grader::ImageVerdict v = grader::compareDeterministic(reference, renderWithOffset(figureScene("lab6_light_below"), -8.f));
    CHECK_FALSE(v.passed);
    MESSAGE("8 spacings under: " << v.reason);
}

} // TEST_SUITE
