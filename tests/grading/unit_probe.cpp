// A probe typed once (grader/protocol/probe.h): its calls send the inputs' numbers in order, its
// answers are read back as the types say, an answer of the wrong shape is refused before it is read,
// and the agent's side calls a function of the probe's very type (what RAYLAB_REGISTER_PROBE
// registers). Probes of this test's own, not a lab's.
#include "grader/protocol/probe.h"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>

namespace protocol = raylab::grader::protocol;

namespace {

struct Segment {
    glm::dvec3 from{0.}, to{0.};
    static constexpr auto fields = std::tuple{&Segment::from, &Segment::to};
};
struct Crossing {
    bool found = false;
    int side = 0;
    double t = 0.;
    std::vector<glm::dvec3> points;
    static constexpr auto fields = std::tuple{&Crossing::found, &Crossing::side, &Crossing::t, &Crossing::points};
};

using CrossProbe = protocol::Probe<Crossing(Segment, double, int)>;
using PickProbe = protocol::Probe<glm::dvec3(bool)>;
const CrossProbe kCross{"test.cross"};
const PickProbe kPick{"test.pick"};

// The agent's function: `count` points along the segment, each `step` further.
Crossing cross(Segment s, double step, int count) {
    Crossing c{count > 0, count % 2 == 0 ? 1 : -1, step * count, {}};
    for (int k = 0; k < count; ++k) c.points.push_back(s.from + (step * k) * (s.to - s.from));
    return c;
}

glm::dvec3 pick(bool up) { return up ? glm::dvec3(0., 1., 0.) : glm::dvec3(0., -1., 0.); }

bool fits(const protocol::ProbeSpec* probe, std::vector<double> numbers) { return probe->fits(numbers); }

} // namespace

TEST_SUITE("typed probes") {

TEST_CASE("a typed probe's call sends its inputs' numbers in order, and its spec counts them") {
    const protocol::Call call = kCross({{1., 2., 3.}, {4., 5., 6.}}, 0.5, 3);
    CHECK(call.probe == kCross.spec());
    CHECK(call.inputs == std::vector<double>{1., 2., 3., 4., 5., 6., 0.5, 3.});
    CHECK(kCross.spec()->inputs == 8);
    CHECK(protocol::probeNamed("test.cross") == kCross.spec());
    const auto [segment, step, count] = kCross.inputs(call.inputs);
    CHECK(segment.to == glm::dvec3(4., 5., 6.));
    CHECK(step == 0.5);
    CHECK(count == 3);
}

TEST_CASE("the agent answers with the function of the probe's type; the parent reads the answer back") {
    const protocol::Call call = kCross({{0., 0., 0.}, {2., 0., 0.}}, 0.25, 2);
    const std::vector<double> numbers = CrossProbe::answerWith(&cross, call.inputs);
    // found, side, t, then the list: its length and its points.
    CHECK(numbers == std::vector<double>{1., 1., 0.5, 2., 0., 0., 0., 0.5, 0., 0.});
    REQUIRE(kCross.spec()->fits(numbers));
    const Crossing answer = kCross.answer(numbers);
    CHECK(answer.found);
    CHECK(answer.side == 1);
    CHECK(answer.t == 0.5);
    REQUIRE(answer.points.size() == 2);
    CHECK(answer.points[1] == glm::dvec3(0.5, 0., 0.));
    CHECK(kPick.answer(PickProbe::answerWith(&pick, kPick(false).inputs)) == glm::dvec3(0., -1., 0.));
}

TEST_CASE("an answer of the wrong shape is refused before it is read; a NaN is a value") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const protocol::ProbeSpec* probe = kCross.spec();
    CHECK(fits(probe, {0., -1., nan, 0.}));                  // no point: a list of length 0
    CHECK_FALSE(fits(probe, {0., -1., 1.}));                 // the list's length is missing
    CHECK_FALSE(fits(probe, {0., -1., 1., 0., 7.}));         // a number too many
    CHECK_FALSE(fits(probe, {0., -1., 1., 1., 0., 0.}));     // a point cut short
    CHECK_FALSE(fits(probe, {0.5, -1., 1., 0.}));            // a bool is 0 or 1
    CHECK_FALSE(fits(probe, {1., 1.5, 1., 0.}));             // an int is whole
    CHECK_FALSE(fits(probe, {1., 3e9, 1., 0.}));             // and within int's range
    CHECK_FALSE(fits(probe, {1., nan, 1., 0.}));
    CHECK_FALSE(fits(probe, {1., 1., 1., -1.}));             // a length is not negative
    CHECK_FALSE(fits(probe, {1., 1., 1., 1.5, 0., 0., 0.})); // nor fractional
    CHECK_FALSE(fits(probe, {1., 1., 1., protocol::kMaxItems + 1.})); // nor beyond what an honest answer holds
    CHECK(fits(kPick.spec(), {nan, 0., 1.}));
    CHECK_FALSE(fits(kPick.spec(), {0., 1.}));
}

} // TEST_SUITE
