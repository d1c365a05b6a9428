#include "grader/judge/checks/checks.h"

#include "src/messages.h"
#include "src/name_registry.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <algorithm>
#include <iterator>
#include <map>
#include <set>
#include <stdexcept>
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

namespace {

// Built on first use: the labs' checks register during static initialisation, in any order of files.
NameRegistry<CheckMaker>& registeredLabs() {
    static NameRegistry<CheckMaker> registry("lab checks");
    return registry;
}

[[noreturn]] void refuse(const std::vector<std::string>& problems) {
    std::string text;
    for (const std::string& p : problems)
        text += (text.empty() ? "" : "\n") + p;
    throw std::runtime_error(text);
}

} // namespace

void registerChecks(const std::string& labId, CheckMaker maker, SourcePlace where) {
    registeredLabs().add(labId, maker, where);
}

std::vector<FunctionCheck> labChecks(const LabDescription& lab, CaseRandom& random) {
    const auto* registered = registeredLabs().find(lab.id);
    std::vector<std::string> problems;
    const std::string labToml = lab.file.string();
    if (registered == nullptr) {
        for (const LabCheck& c : lab.checks)
            problems.push_back(
                tr("check.lab_without_code",
                   {{"lab_toml", labToml}, {"line", std::to_string(c.line)}, {"name", c.name}, {"id", lab.id}}));
        if (!problems.empty()) refuse(problems);
        return {};
    }
    LabChecks added;
    registered->value(added, random);
    std::vector<FunctionCheck> checks;
    std::set<std::string> coded;
    for (LabChecks::Added& a : added.added()) {
        const LabCheck* declared = lab.check(a.check.name);
        if (declared == nullptr) {
            problems.push_back(tr("check.not_in_lab_toml",
                                  {{"where", a.where.shown()}, {"name", a.check.name}, {"lab_toml", labToml}}));
            continue;
        }
        coded.insert(a.check.name);
        a.check.lab = lab.number;
        a.check.points = declared->points;
        checks.push_back(std::move(a.check));
    }
    for (const LabCheck& c : lab.checks)
        if (coded.count(c.name) == 0)
            problems.push_back(tr("check.no_code", {{"lab_toml", labToml},
                                                    {"line", std::to_string(c.line)},
                                                    {"name", c.name},
                                                    {"registered", registered->where.shown()}}));
    if (!problems.empty()) refuse(problems);
    return checks;
}

std::vector<FunctionCheck> functionChecks(const LabCatalog& labs, std::uint64_t seed) {
    std::vector<std::string> problems;
    for (const std::string& id : registeredLabs().names())
        if (std::none_of(labs.labs.begin(), labs.labs.end(), [&](const LabDescription& l) { return l.id == id; }))
            problems.push_back(tr("check.unknown_lab", {{"where", registeredLabs().find(id)->where.shown()}, {"id", id}}));
    if (!problems.empty()) refuse(problems);
    CaseRandom random(seed); // one generator through the labs in order: each lab draws after the one before
    std::vector<FunctionCheck> checks;
    for (const LabDescription& lab : labs.labs) {
        std::vector<FunctionCheck> own = labChecks(lab, random);
        checks.insert(checks.end(), std::make_move_iterator(own.begin()), std::make_move_iterator(own.end()));
    }
    return checks;
}

} // namespace raylab::grader
