// Valid variants (tests/instructors/variants/) are correct solutions written differently: they must pass.
#include "grading_support.h"

using namespace raylab::test;

TEST_SUITE("variants") {

TEST_CASE("double precision, truncating quantization, another generator, stratified sampling, an unnormalized shadow ray "
          "and a student's own labs 2 to 6 pass") {
    // independent_student: labs 2 to 6 written from the handouts in one program, each lab over the
    // student's own earlier labs as in the students' tree. Its hit points, a rounding away from the
    // reference's, shadowed 2 pixels of lab6_light_below's terminator before the references' probe of
    // shadow rays (docs/grading.md, "Deterministic figures"): 91 / 93.
    for (const char* variant : {"double_precision", "truncating_quantization", "own_random_generator", "stratified_sampling",
                                "shadow_ray_to_the_light", "independent_student"}) {
        const GradeResult r = gradeAgent(courseSetup(), std::string("raylab-variant-") + variant);
        CHECK_MESSAGE(r.allPassed(), std::string(variant) << failures(r));
        CHECK(r.score() == r.maxScore());
    }
}

} // TEST_SUITE
