// A check's hint names the cause its outputs show, never one the code does not have: lab 1's
// checks judged on made-up gradients (no agent runs).
#include "grader/checks/checks.h"

#include <doctest/doctest.h>

#include <functional>
#include <string>
#include <vector>

using namespace raylab::grader;

namespace {

using Fill = std::function<glm::dvec3(int i, int j, int width, int height)>;

double ramp(int k, int n) { return n > 1 ? double(k) / (n - 1) : 0.; }

using Answer = std::function<std::vector<double>(const protocol::Call&)>;
using AddChecks = void (*)(std::vector<FunctionCheck>&, CaseRandom&);

// Every check of a lab (or the one named `only`) judged on what `answer` returns to its calls; its
// message (empty when it passes) by name.
std::vector<std::pair<std::string, std::string>> judge(AddChecks addChecks, const Answer& answer, const std::string& only = "") {
    std::vector<FunctionCheck> checks;
    CaseRandom random(2026);
    addChecks(checks, random);
    std::vector<std::pair<std::string, std::string>> messages;
    for (const FunctionCheck& check : checks) {
        if (!only.empty() && check.name != only) continue;
        std::vector<std::vector<double>> outputs;
        for (const auto& call : check.calls) outputs.push_back(answer(call));
        Judge judge;
        check.judge(outputs, judge);
        messages.emplace_back(check.name, judge.message());
    }
    return messages;
}

// Lab 1's checks on the gradient `fill` draws.
std::vector<std::pair<std::string, std::string>> judgeLab1(const Fill& fill) {
    return judge(addLab1Checks, [&fill](const protocol::Call& call) {
        const int width = int(call.inputs[0]), height = int(call.inputs[1]);
        std::vector<double> out;
        for (int j = 0; j < height; ++j)
            for (int i = 0; i < width; ++i) {
                const glm::dvec3 p = fill(i, j, width, height);
                out.insert(out.end(), {p.x, p.y, p.z});
            }
        return out;
    });
}

bool says(const std::string& message, const char* words) { return message.find(words) != std::string::npos; }

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
        const std::string name = "computeNormal: unit and pointing outwards";
        const auto messages = judge(
            addLab3Checks,
            [inward](const protocol::Call& call) {
                const glm::dvec3 centre(call.inputs[0], call.inputs[1], call.inputs[2]),
                    point(call.inputs[4], call.inputs[5], call.inputs[6]);
                const double radius = call.inputs[3];
                const glm::dvec3 n = inward ? (centre - point) / radius : point - centre;
                return std::vector<double>{n.x, n.y, n.z};
            },
            name);
        REQUIRE(messages.size() == 1);
        const std::string& message = messages[0].second;
        CHECK_FALSE(message.empty());
        CHECK_MESSAGE(says(message, "it points from the centre outwards") == inward, message);
        CHECK_MESSAGE(says(message, "divide by the radius") == !inward, message);
    }
}

}
