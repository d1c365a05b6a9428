// A check's hint names the cause its outputs show, never one the code does not have: lab 1's
// checks judged on made-up gradients (no agent runs). Lab 4's case is a suite of its own, skipped where
// the course does not hand lab 4 out.
#include "grader/judge/checks/checks.h"
#include "grader/labs/lab1_first_image/probes.h"
#include "grader/labs/lab2_primary_rays/probes.h"
#include "grader/labs/lab3_sphere/probes.h"
#include "grader/labs/lab4_lookat_camera/probes.h"
#include "src/messages.h"
#include "support/course.h"

#include <doctest/doctest.h>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>
#include <filesystem>

#include <functional>
#include <string>
#include <vector>

using namespace raylab::grader;

namespace {

using Fill = std::function<glm::dvec3(int i, int j, int width, int height)>;

double ramp(int k, int n) { return n > 1 ? double(k) / (n - 1) : 0.; }

// The camera the lookAt constructor builds on the frame u, v, w: the screen placed as updateViewport does.
probes::BuiltCamera built(const probes::LookAtCamera& c, const glm::dvec3& u, const glm::dvec3& v, const glm::dvec3& w) {
    const double h = 2. * std::tan(glm::radians(c.fovy) / 2.), wide = h * c.width / c.height;
    return {u, v, w, c.position, h, wide, c.position - w + v * (h / 2.) - u * (wide / 2.)};
}

using Answer = std::function<std::vector<double>(const protocol::Call&)>;
// Every check of a lab (or the one named `only`) judged on what `answer` returns to its calls; its
// message (empty when it passes) by name.
std::vector<std::pair<std::string, std::string>> judge(int lab, const Answer& answer, const std::string& only = "") {
    const LabCatalog labs = loadLabCatalog(std::filesystem::path(RAYLAB_SOURCE_DIR) / "labs");
    CaseRandom random(2026);
    REQUIRE_MESSAGE(labs.lab(lab) != nullptr, "lab " << lab << " is not in this course");
    const std::vector<FunctionCheck> checks = labChecks(*labs.lab(lab), random);
    std::vector<std::pair<std::string, std::string>> messages;
    for (const FunctionCheck& check : checks) {
        if (!only.empty() && check.id != only) continue;
        std::vector<std::vector<double>> outputs;
        for (const auto& call : check.calls) outputs.push_back(answer(call));
        Judge judge;
        check.judge(outputs, judge);
        messages.emplace_back(check.id, judge.message());
    }
    return messages;
}

// Lab 1's checks on the gradient `fill` draws.
std::vector<std::pair<std::string, std::string>> judgeLab1(const Fill& fill) {
    return judge(1, [&fill](const protocol::Call& call) {
        const auto [width, height] = probes::fillGradient.inputs(call.inputs);
        std::vector<glm::dvec3> pixels;
        for (int j = 0; j < height; ++j)
            for (int i = 0; i < width; ++i) pixels.push_back(fill(i, j, width, height));
        return probes::fillGradient.answerNumbers(pixels);
    });
}

bool says(const std::string& message, const char* words) { return message.find(words) != std::string::npos; }

// The messages in `language` while it lives, then in the language before.
struct LanguageScope {
    explicit LanguageScope(raylab::Language language) : previous(raylab::language()) { raylab::setLanguage(language); }
    ~LanguageScope() { raylab::setLanguage(previous); }
    raylab::Language previous;
};

} // namespace

TEST_SUITE("hints") {

TEST_CASE("lab 1: a flipped green ramp is told the ramp, not a missed pixel nor a division by zero") {
    for (const auto& [name, message] : judgeLab1([](int i, int j, int w, int h) {
             return glm::dvec3(ramp(i, w), ramp(h - 1 - j, h), 0.);
         })) {
        CAPTURE(name);
        CHECK_FALSE(message.empty()); // every check sees it
        CHECK_MESSAGE(says(message, "green = j / (H - 1) downwards"), message);
        CHECK_MESSAGE(!says(message, "loop over every column"), message);
        CHECK_MESSAGE(!says(message, "instead of dividing by 0"), message);
    }
}

TEST_CASE("lab 1: a texture of another size is told its count of pixels, and no pixel past its end is read") {
    const auto messages = judge(1, [](const protocol::Call& call) {
        const auto [width, height] = probes::fillGradient.inputs(call.inputs);
        return probes::fillGradient.answerNumbers(std::vector<glm::dvec3>(std::size_t(width) * std::size_t(height) - 1, glm::dvec3(0.)));
    });
    REQUIRE_FALSE(messages.empty());
    for (const auto& [name, message] : messages) {
        CAPTURE(name);
        CHECK_MESSAGE(says(message, "its number of pixels"), message);
        CHECK_MESSAGE(says(message, "without resizing it"), message);
    }
}

TEST_CASE("lab 1: a pixel never written, a division by zero and an integer division are each named") {
    const auto lastColumnMissed = judgeLab1([](int i, int j, int w, int h) {
        return i == w - 1 ? glm::dvec3(-1.) : glm::dvec3(ramp(i, w), ramp(j, h), 0.);
    });
    CHECK_MESSAGE(says(lastColumnMissed[1].second, "loop over every column"), lastColumnMissed[1].second);

    const auto dividedByZero = judgeLab1([](int i, int j, int w, int h) {
        return glm::dvec3(double(i) / (w - 1), double(j) / (h - 1), 0.);
    });
    CHECK(dividedByZero[0].second.empty());
    CHECK(dividedByZero[1].second.empty());
    CHECK_MESSAGE(says(dividedByZero[2].second, "instead of dividing by 0"), dividedByZero[2].second);

    const auto integerDivision = judgeLab1([](int i, int j, int w, int h) {
        return glm::dvec3(w > 1 ? double(i / (w - 1)) : 0., h > 1 ? double(j / (h - 1)) : 0., 0.);
    });
    CHECK_MESSAGE(says(integerDivision[0].second, "not in integers"), integerDivision[0].second);
}

TEST_CASE("lab 3: an inward normal is told to point outwards, a normal of length r to divide by r") {
    for (const bool inward : {true, false}) {
        CAPTURE(inward);
        const std::string name = "normal";
        const auto messages = judge(
            3,
            [inward](const protocol::Call& call) {
                const auto [sphere, point] = probes::computeNormal.inputs(call.inputs);
                return probes::computeNormal.answerNumbers(inward ? (sphere.centre - point) / sphere.radius : point - sphere.centre);
            },
            name);
        REQUIRE(messages.size() == 1);
        const std::string& message = messages[0].second;
        CHECK_FALSE(message.empty());
        CHECK_MESSAGE(says(message, "it points from the centre outwards") == inward, message);
        CHECK_MESSAGE(says(message, "divide by the radius") == !inward, message);
    }
}

TEST_CASE("lab 2: sx and sy swapped is not blamed on the position of a camera away from the origin") {
    // generateRay with sx and sy swapped, the viewport right (docs/conventions.md's default frame).
    const auto screen = [](int width, int height, double fovy) {
        const double h = 2. * std::tan(glm::radians(fovy) / 2.);
        return probes::Viewport{h, h * width / height, glm::dvec3(h * width / height / 2., h / 2., 1.)};
    };
    auto swapped = [&screen](const protocol::Call& call) {
        if (call.probe == probes::viewport.spec())
            return probes::viewport.answerNumbers(std::apply(screen, probes::viewport.inputs(call.inputs)));
        const auto [camera, sx, sy] = probes::generateRay.inputs(call.inputs);
        const probes::Viewport v = screen(camera.width, camera.height, camera.fovy);
        const glm::dvec3 d = glm::normalize(glm::dvec3(v.width / 2. - sy * v.width, v.height / 2. - sx * v.height, 1.)); // the mistake
        return probes::generateRay.answerNumbers({camera.position, d});
    };
    const auto messages = judge(2, swapped, "moved_camera");
    REQUIRE(messages.size() == 1);
    const std::string& message = messages[0].second;
    CHECK_FALSE(message.empty());
    CHECK_MESSAGE(!says(message, "topLeft includes the position"), message);
    CHECK_MESSAGE(says(message, "the position is not the cause"), message);
}

}

TEST_SUITE("hints: lab 4") {

TEST_CASE("lab 4: u and v made rightly from an unnormalized w are sent to w, and so is the screen") {
    if (!raylab::test::labInCourse(std::filesystem::path(RAYLAB_SOURCE_DIR) / "labs", 4)) return;
    // The lookAt constructor with w = position - target, the rest as the handout says.
    auto unnormalizedW = [](const protocol::Call& call) {
        if (call.probe != probes::lookAt.spec()) return probes::lookAtRefused.answerNumbers(true);
        const auto [c] = probes::lookAt.inputs(call.inputs);
        const glm::dvec3 w = c.position - c.target, u = glm::normalize(glm::cross(c.up, w)), v = glm::cross(w, u);
        return probes::lookAt.answerNumbers(built(c, u, v, w));
    };
    for (const char* name : {"four_cameras", "viewport_follows"}) {
        const auto messages = judge(4, unnormalizedW, name);
        REQUIRE(messages.size() == 1);
        const std::string& message = messages[0].second;
        CAPTURE(name);
        CHECK_FALSE(message.empty());
        CHECK_MESSAGE(!says(message, "v = cross(w, u), up in the image"), message);
        CHECK_MESSAGE(!says(message, "call updateViewport()"), message);
        const bool sentToTheFrame = says(message, "fix w first") || says(message, "that frame is wrong");
        CHECK_MESSAGE(sentToTheFrame, message);
    }
}

} // TEST_SUITE

TEST_SUITE("hints") {

TEST_CASE("a hint names a mistake only on that mistake's evidence; otherwise it says how the values relate") {
    const LanguageScope english(raylab::Language::En);
    const std::vector<Suspect<glm::dvec3>> suspects{{{0., -1., 0.}, "v = cross(u, w) points down"}};
    {
        Judge judge; // the value the suspect gives: its hint
        CHECK_FALSE(judge.expectNear("v", {0., -1., 0.}, {0., 1., 0.}, 1e-6, "v = cross(w, u)", suspects));
        CHECK_MESSAGE(says(judge.message(), "Hint: v = cross(u, w) points down"), judge.message());
        CHECK_MESSAGE(says(judge.message(), "(the opposite vector, every sign flipped)"), judge.message());
    }
    {
        Judge judge; // another wrong value: the formula and what they share, no mistake named
        CHECK_FALSE(judge.expectNear("v", {0., 2., 0.}, {0., 1., 0.}, 1e-6, "v = cross(w, u)", suspects));
        CHECK_MESSAGE(says(judge.message(), "Hint: v = cross(w, u)"), judge.message());
        CHECK_MESSAGE(!says(judge.message(), "points down"), judge.message());
        CHECK_MESSAGE(says(judge.message(), "(the same direction, 2 times the expected length)"), judge.message());
    }
    {
        Judge judge; // a suspect that gives the expected value too tells nothing
        const std::vector<Suspect<double>> same{{1.5 + 4e-6, "a mistake"}};
        CHECK_FALSE(judge.expectNear("t", 1.5 + 8e-6, 1.5, 5e-6, "t = the near root", same));
        CHECK_MESSAGE(!says(judge.message(), "a mistake"), judge.message());
    }
    {
        Judge judge; // right: no message
        CHECK(judge.expectNear("v", {0., 1., 0.}, {0., 1., 0.}, 1e-6, "v = cross(w, u)", suspects));
        CHECK(judge.message().empty());
    }
}

TEST_CASE("what a wrong value shares with the expected one, in words") {
    const LanguageScope english(raylab::Language::En);
    const glm::dvec3 e{1., 2., 3.};
    CHECK(relation(-e, e, 1e-6) == "the opposite vector, every sign flipped");
    CHECK(relation({1., -2., 3.}, e, 1e-6) == "the expected vector with the sign of y flipped");
    CHECK(relation({2., 1., 3.}, e, 1e-6) == "the expected components with x and y exchanged");
    CHECK(relation(2.5 * e, e, 1e-6) == "the same direction, 2.5 times the expected length");
    CHECK(relation(-0.5 * e, e, 1e-6) == "the opposite direction, 0.5 times the expected length");
    CHECK(relation({0., 0.6, 0.8}, {1., 0., 0.}, 1e-6) == "the same length, 90° from the expected direction");
    CHECK(relation({0., 0., 1.}, {1., 0., 0.}, 1e-6) == "the expected components with x and z exchanged");
    CHECK(relation({0., 0., 3.}, {1., 0., 0.}, 1e-6) == "90° from the expected direction, 3 times the expected length");
    CHECK(relation({0., 0., 0.}, e, 1e-6) == "the zero vector");
    CHECK(relation({std::nan(""), 0., 0.}, e, 1e-6) == "not a number");
    CHECK(relation(e, {0., 0., 0.}, 1e-6).empty()); // nothing to share with the zero vector
    CHECK(relation(-2., 2., 1e-6) == "the opposite sign");
    CHECK(relation(6., 2., 1e-6) == "3 times the expected value");
    const LanguageScope french(raylab::Language::Fr);
    CHECK(relation(2.5 * e, e, 1e-6) == "la même direction, 2,5 fois la longueur attendue");
}

} // TEST_SUITE

TEST_SUITE("hints: lab 4") {

// The lookAt constructor's answer for a frame made by `frame` (u, v from position, target and up),
// the screen placed in it as updateViewport does.
Answer lookAtAnswer(std::function<void(const glm::dvec3& w, const glm::dvec3& up, glm::dvec3& u, glm::dvec3& v)> frame) {
    return [frame](const protocol::Call& call) {
        if (call.probe != probes::lookAt.spec()) return probes::lookAtRefused.answerNumbers(true);
        const auto [c] = probes::lookAt.inputs(call.inputs);
        const glm::dvec3 w = glm::normalize(c.position - c.target);
        glm::dvec3 u, v;
        frame(w, c.up, u, v);
        return probes::lookAt.answerNumbers(built(c, u, v, w));
    };
}

TEST_CASE("lab 4: u and v exchanged are told so, not the order of cross(up, w); a mirrored u is told its order, v sent to u") {
    if (!raylab::test::labInCourse(std::filesystem::path(RAYLAB_SOURCE_DIR) / "labs", 4)) return;
    const LanguageScope english(raylab::Language::En);
    const std::string basis = "four_cameras";
    const std::string exchanged = judge(4, lookAtAnswer([](const glm::dvec3& w, const glm::dvec3& up, glm::dvec3& u, glm::dvec3& v) {
                                            v = glm::normalize(glm::cross(up, w));
                                            u = glm::cross(w, v);
                                        }),
                                        basis)[0].second;
    CHECK_MESSAGE(says(exchanged, raylab::tr("hint.lab4.u_v_exchanged").c_str()), exchanged);
    for (const char* other : {"hint.lab4.u_order", "hint.lab4.v_order", "hint.lab4.u_unit", "hint.lab4.v_is_up"})
        CHECK_MESSAGE(!says(exchanged, raylab::tr(other).c_str()), std::string(other) << ": " << exchanged);
    CHECK_MESSAGE(!says(exchanged, "cross(w, up)"), exchanged);

    const std::string mirrored = judge(4, lookAtAnswer([](const glm::dvec3& w, const glm::dvec3& up, glm::dvec3& u, glm::dvec3& v) {
                                           u = glm::normalize(glm::cross(w, up));
                                           v = glm::cross(w, u);
                                       }),
                                       basis)[0].second;
    CHECK_MESSAGE(says(mirrored, raylab::tr("hint.lab4.u_order").c_str()), mirrored);
    CHECK_MESSAGE(says(mirrored, raylab::tr("hint.lab4.from_u").c_str()), mirrored);
    CHECK_MESSAGE(!says(mirrored, raylab::tr("hint.lab4.v_order").c_str()), mirrored);

    // A u that is no classic mistake (turned about w by a quarter of a right angle): the formula and
    // how it relates, no mistake named.
    const std::string turned = judge(4, lookAtAnswer([](const glm::dvec3& w, const glm::dvec3& up, glm::dvec3& u, glm::dvec3& v) {
                                         const glm::dvec3 right = glm::normalize(glm::cross(up, w)), top = glm::cross(w, right);
                                         u = std::cos(0.4) * right + std::sin(0.4) * top;
                                         v = top;
                                     }),
                                     basis)[0].second;
    CHECK_MESSAGE(says(turned, ("Hint: " + raylab::tr("hint.lab4.u")).c_str()), turned);
    CHECK_MESSAGE(says(turned, "the same length, 22.9° from the expected direction"), turned);
    for (const char* other : {"hint.lab4.u_order", "hint.lab4.u_unit", "hint.lab4.u_v_exchanged"})
        CHECK_MESSAGE(!says(turned, raylab::tr(other).c_str()), std::string(other) << ": " << turned);
}

} // TEST_SUITE
