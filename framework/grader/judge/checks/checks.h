#pragma once
// The function checks, judged by the parent: each check draws its inputs (fixed hard cases, and
// cases drawn at grading time the child cannot predict), has the child call the student's
// functions on them through probes (protocol.h), and decides from the raw outputs, in double,
// with a message that says what was expected, what came and a hint.

#include "grader/lab_catalog.h"
#include "grader/protocol/protocol.h"
#include "src/name_registry.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <functional>
#include <random>
#include <string>
#include <vector>

namespace raylab::grader {

// A classic mistake a failed expectation may come from: the value that mistake gives, worked out
// for the case, and the hint that names it. A hint that names a mistake is given only on that
// evidence (the value got is the value it gives, within the expectation's tolerance): a wrong value
// that no suspect gives is told the formula and how it relates to the expected one, no guess.
template <class Value>
struct Suspect {
    Value gives;
    std::string hint;
};

// Collects a check's failed expectations: "WHAT: expected E, got G (how they relate). Hint: H", one
// a line; the failures that share a hint are one line, the first, and how many more there are.
class Judge {
public:
    void fail(const std::string& what, const std::string& expected, const std::string& got, const std::string& hint);
    // `hint` says what is right (the formula) and names no mistake; the first of `suspects` whose
    // value is the one got (within `tolerance`) gives its hint instead.
    bool expectNear(const std::string& what, double got, double expected, double tolerance, const std::string& hint,
                    const std::vector<Suspect<double>>& suspects = {});
    bool expectNear(const std::string& what, const glm::dvec3& got, const glm::dvec3& expected, double tolerance,
                    const std::string& hint, const std::vector<Suspect<glm::dvec3>>& suspects = {});
    bool expectTrue(const std::string& what, bool holds, const std::string& expected, const std::string& got,
                    const std::string& hint);
    bool passed() const { return m_failures.empty(); }
    std::string message() const;

private:
    // As fail, the line also saying how the value got relates to the expected one (when `related` is not empty).
    void failRelated(const std::string& what, const std::string& expected, const std::string& got,
                     const std::string& related, const std::string& hint);
    struct Failure {
        std::string line, hint;
    };
    std::vector<Failure> m_failures;
};

// Each component of a within `tolerance` of b's.
bool withinEach(const glm::dvec3& a, const glm::dvec3& b, double tolerance);

// What a wrong value got shares with the expected one, in words (empty when nothing simple):
// the opposite, a factor between them, the same direction or length, a sign flipped, two
// components exchanged. Facts only: it names no mistake.
std::string relation(const glm::dvec3& got, const glm::dvec3& expected, double tolerance);
std::string relation(double got, double expected, double tolerance);

std::string show(double v);
std::string show(const glm::dvec3& v);

struct FunctionCheck {
    std::string id; // as its lab's lab.toml declares it
    std::vector<protocol::Call> calls;
    // Judges the outputs of `calls` (one list a call, each of the size its probe gives).
    std::function<void(const std::vector<std::vector<double>>& outputs, Judge& judge)> judge;
    int lab = 0;        // the lab's number, from its lab.toml
    double points = 0.; // from its lab.toml
};

// Where the drawn cases come from: the parent's own generator, seeded where the child cannot see.
class CaseRandom {
public:
    explicit CaseRandom(std::uint64_t seed) : m_engine(seed) {}
    double uniform(double low, double high) { return std::uniform_real_distribution<double>(low, high)(m_engine); }
    int integer(int low, int high) { return std::uniform_int_distribution<int>(low, high)(m_engine); }
    glm::dvec3 vec3(double low, double high) { return {uniform(low, high), uniform(low, high), uniform(low, high)}; }
    glm::dvec3 unitVector();
    // A float-exact copy: the child receives floats, so the parent reasons on the same numbers.
    static double asFloat(double v) { return double(float(v)); }
    static glm::dvec3 asFloat(const glm::dvec3& v) { return {asFloat(v.x), asFloat(v.y), asFloat(v.z)}; }

private:
    std::mt19937_64 m_engine;
};

// A lab's checks, as its grading folder adds them (framework/grader/labs/<lab>/checks.cpp), each by
// the name its lab.toml declares; `where` is the line that adds it, for the catalogue's errors.
class LabChecks {
public:
    struct Added {
        FunctionCheck check;
        SourcePlace where;
    };
    void add(FunctionCheck check, SourcePlace where = SourcePlace::here()) {
        m_added.push_back({std::move(check), where});
    }
    std::vector<Added>& added() { return m_added; }

private:
    std::vector<Added> m_added;
};

using CheckMaker = void (*)(LabChecks& checks, CaseRandom& random);

// Adds the checks of the lab whose id (its folder's name) is `labId`; a lab registered twice is a
// std::logic_error naming both places.
void registerChecks(const std::string& labId, CheckMaker maker, SourcePlace where);

struct ChecksRegistrar {
    ChecksRegistrar(const std::string& labId, CheckMaker maker,
                    SourcePlace where = SourcePlace::here()) {
        registerChecks(labId, maker, where);
    }
};

// One lab's checks, their drawn cases from `random`, each with its number and points. Throws
// std::runtime_error naming both places (file:line) when a check of the code is not in the lab's
// lab.toml, or one of lab.toml has no code.
std::vector<FunctionCheck> labChecks(const LabDescription& lab, CaseRandom& random);

// Every lab's checks in the order of the labs, their drawn cases from `seed`. Throws as labChecks,
// and when checks are registered for a lab that no lab.toml describes.
std::vector<FunctionCheck> functionChecks(const LabCatalog& labs, std::uint64_t seed);

} // namespace raylab::grader

// At namespace scope in a lab's checks.cpp: RAYLAB_REGISTER_CHECKS(addChecks). The lab is the grading
// folder's: CMake defines RAYLAB_LAB_ID, its folder's name, for the files of each grading folder.
#define RAYLAB_REGISTER_CHECKS(maker) RAYLAB_REGISTRAR(::raylab::grader::ChecksRegistrar)(RAYLAB_LAB_ID, (maker))
