#include "grader/judge/checks/checks.h"

#include "src/messages.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <map>
#include <utility>

namespace raylab::grader {

std::string show(double v) { return formatNumber(v, 7); }

std::string show(const glm::dvec3& v) {
    return tr("number.vector", {{"x", formatNumber(v.x, 6)}, {"y", formatNumber(v.y, 6)}, {"z", formatNumber(v.z, 6)}});
}

void Judge::fail(const std::string& what, const std::string& expected, const std::string& got,
                 const std::string& hint) {
    m_failures.push_back({tr("check.failure", {{"what", what}, {"expected", expected}, {"got", got}, {"hint", hint}}), hint});
}

// A NaN is never near anything: the comparisons are written so that it fails them.
bool Judge::expectNear(const std::string& what, double got, double expected, double tolerance,
                       const std::string& hint) {
    if (std::abs(got - expected) <= tolerance) return true;
    fail(what, tr("check.within", {{"value", show(expected)}, {"tolerance", show(tolerance)}}), show(got), hint);
    return false;
}

bool Judge::expectNear(const std::string& what, const glm::dvec3& got, const glm::dvec3& expected, double tolerance,
                       const std::string& hint) {
    if (withinEach(got, expected, tolerance)) return true;
    fail(what, tr("check.within", {{"value", show(expected)}, {"tolerance", show(tolerance)}}), show(got), hint);
    return false;
}

bool withinEach(const glm::dvec3& a, const glm::dvec3& b, double tolerance) {
    const glm::dvec3 d = glm::abs(a - b);
    return d.x <= tolerance && d.y <= tolerance && d.z <= tolerance;
}

bool Judge::expectTrue(const std::string& what, bool holds, const std::string& expected, const std::string& got,
                       const std::string& hint) {
    if (!holds) fail(what, expected, got, hint);
    return holds;
}

std::string Judge::message() const {
    std::vector<std::pair<std::string, int>> lines; // a hint's first failure, and how many more share it
    std::map<std::string, std::size_t> lineOfHint;
    for (const Failure& f : m_failures) {
        const auto [at, first] = lineOfHint.emplace(f.hint, lines.size());
        if (first) lines.emplace_back(f.line, 0);
        else ++lines[at->second].second;
    }
    std::string text;
    for (const auto& [line, more] : lines) {
        if (!text.empty()) text += '\n';
        text += line;
        if (more > 0) text.append(" ").append(tr("check.same_hint", {{"count", std::to_string(more)}}));
    }
    return text;
}

glm::dvec3 CaseRandom::unitVector() {
    for (;;) {
        const glm::dvec3 v = vec3(-1., 1.);
        const double length = glm::length(v);
        if (length > 0.1 && length <= 1.) return v / length;
    }
}

void appendInputs(std::vector<double>& inputs, const glm::dvec3& v) {
    inputs.insert(inputs.end(), {v.x, v.y, v.z});
}

std::vector<FunctionCheck> functionChecks(std::uint64_t seed) {
    CaseRandom random(seed);
    std::vector<FunctionCheck> checks;
    addLab1Checks(checks, random);
    addLab2Checks(checks, random);
    addLab3Checks(checks, random);
    addLab4Checks(checks, random);
    addLab5Checks(checks, random);
    return checks;
}

} // namespace raylab::grader
