// Valid variants (tests/variants/) are correct solutions written differently: they must pass.
#include "grading_support.h"

using namespace raylab::test;

TEST_SUITE("variants") {

TEST_CASE("double precision, truncating quantization, another generator, stratified sampling and an unnormalized shadow ray pass") {
    for (const char* variant : {"double_precision", "truncating_quantization", "own_random_generator", "stratified_sampling",
                                "shadow_ray_to_the_light"}) {
        const GradeResult r = gradeAgent(courseSetup(), std::string("raylab-variant-") + variant);
        CHECK_MESSAGE(r.allPassed(), std::string(variant) << failures(r));
        CHECK(r.score() == r.maxScore());
    }
}

} // TEST_SUITE
