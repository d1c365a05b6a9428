#include "grader/judge/checks/checks.h"

#include "src/messages.h"
#include "src/name_registry.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <numbers>
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

void Judge::failRelated(const std::string& what, const std::string& expected, const std::string& got,
                        const std::string& related, const std::string& hint) {
    if (related.empty()) return fail(what, expected, got, hint);
    m_failures.push_back({tr("check.failure_related",
                             {{"what", what}, {"expected", expected}, {"got", got}, {"relation", related}, {"hint", hint}}),
                          hint});
}

namespace {

// The hint of the first suspect that gives the value got, else the formula's. A suspect that gives
// the expected value too (within the tolerance) is no evidence: this case does not tell it apart.
template <class Value, class Near>
const std::string& evidenced(const std::string& hint, const std::vector<Suspect<Value>>& suspects, const Value& got,
                             const Value& expected, Near near) {
    for (const Suspect<Value>& s : suspects)
        if (near(s.gives, got) && !near(s.gives, expected)) return s.hint;
    return hint;
}

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

std::string degrees(double cosine) { return formatNumber(std::acos(std::clamp(cosine, -1., 1.)) * 180. / std::numbers::pi, 3); }

} // namespace

// A NaN is never near anything: the comparisons are written so that it fails them.
bool Judge::expectNear(const std::string& what, double got, double expected, double tolerance,
                       const std::string& hint, const std::vector<Suspect<double>>& suspects) {
    if (std::abs(got - expected) <= tolerance) return true;
    failRelated(what, tr("check.within", {{"value", show(expected)}, {"tolerance", show(tolerance)}}), show(got),
                relation(got, expected, tolerance),
                evidenced(hint, suspects, got, expected, [tolerance](double a, double b) { return std::abs(a - b) <= tolerance; }));
    return false;
}

bool Judge::expectNear(const std::string& what, const glm::dvec3& got, const glm::dvec3& expected, double tolerance,
                       const std::string& hint, const std::vector<Suspect<glm::dvec3>>& suspects) {
    if (withinEach(got, expected, tolerance)) return true;
    failRelated(what, tr("check.within", {{"value", show(expected)}, {"tolerance", show(tolerance)}}), show(got),
                relation(got, expected, tolerance),
                evidenced(hint, suspects, got, expected,
                          [tolerance](const glm::dvec3& a, const glm::dvec3& b) { return withinEach(a, b, tolerance); }));
    return false;
}

bool withinEach(const glm::dvec3& a, const glm::dvec3& b, double tolerance) {
    const glm::dvec3 d = glm::abs(a - b);
    return d.x <= tolerance && d.y <= tolerance && d.z <= tolerance;
}

std::string relation(const glm::dvec3& got, const glm::dvec3& expected, double tolerance) {
    if (!finite(got)) return tr("check.relation.not_finite");
    const double lengthGot = glm::length(got), lengthExpected = glm::length(expected);
    if (lengthExpected <= tolerance) return ""; // the zero vector shares nothing to say
    if (lengthGot <= tolerance) return tr("check.relation.zero");
    if (withinEach(got, -expected, tolerance)) return tr("check.relation.opposite");
    static const char* const axes[] = {"x", "y", "z"};
    const auto near = [tolerance](double a, double b) { return std::abs(a - b) <= tolerance; };
    for (int k = 0; k < 3; ++k) {
        glm::dvec3 flipped = expected;
        flipped[k] = -flipped[k];
        if (!near(expected[k], 0.) && withinEach(got, flipped, tolerance))
            return tr("check.relation.sign", {{"axis", axes[k]}});
    }
    for (int a = 0; a < 3; ++a)
        for (int b = a + 1; b < 3; ++b) {
            glm::dvec3 exchanged = expected;
            std::swap(exchanged[a], exchanged[b]);
            if (!near(expected[a], expected[b]) && withinEach(got, exchanged, tolerance))
                return tr("check.relation.exchanged", {{"a", axes[a]}, {"b", axes[b]}});
        }
    const double cosine = glm::dot(got, expected) / (lengthGot * lengthExpected);
    const std::string factor = formatNumber(lengthGot / lengthExpected, 4);
    // Parallel: got off the line of expected by no more than the tolerance.
    if (glm::length(glm::cross(got, expected / lengthExpected)) <= tolerance)
        return tr(cosine > 0. ? "check.relation.same_direction" : "check.relation.opposite_direction", {{"factor", factor}});
    if (near(lengthGot, lengthExpected))
        return tr("check.relation.same_length", {{"angle", degrees(cosine)}});
    return tr("check.relation.apart", {{"angle", degrees(cosine)}, {"factor", factor}});
}

std::string relation(double got, double expected, double tolerance) {
    if (!std::isfinite(got)) return tr("check.relation.not_finite");
    if (std::abs(expected) <= tolerance || std::abs(got) <= tolerance) return "";
    if (std::abs(got + expected) <= tolerance) return tr("check.relation.opposite_sign");
    return tr("check.relation.factor", {{"factor", formatNumber(got / expected, 4)}});
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
                   {{"lab_toml", labToml}, {"line", std::to_string(c.line)}, {"name", c.id}, {"id", lab.id}}));
        if (!problems.empty()) refuse(problems);
        return {};
    }
    LabChecks added;
    registered->value(added, random);
    std::vector<FunctionCheck> checks;
    std::set<std::string> coded;
    for (LabChecks::Added& a : added.added()) {
        const LabCheck* declared = lab.check(a.check.id);
        if (declared == nullptr) {
            problems.push_back(tr("check.not_in_lab_toml",
                                  {{"where", a.where.shown()}, {"name", a.check.id}, {"lab_toml", labToml}}));
            continue;
        }
        coded.insert(a.check.id);
        a.check.lab = lab.number;
        a.check.points = declared->points;
        checks.push_back(std::move(a.check));
    }
    for (const LabCheck& c : lab.checks)
        if (coded.count(c.id) == 0)
            problems.push_back(tr("check.no_code", {{"lab_toml", labToml},
                                                    {"line", std::to_string(c.line)},
                                                    {"name", c.id},
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
