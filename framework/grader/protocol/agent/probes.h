#pragma once
// The child's half of the function checks: each probe calls one student function with the inputs
// the parent drew and returns what came out, unjudged. A lab's grading folder registers its probes
// (framework/grader/labs/<lab>/probes.cpp), by the name its probes.h declares:
//
//   RAYLAB_REGISTER_PROBE(fillGradient, fillGradientProbe);  // at namespace scope

#include "grader/protocol/protocol.h"
#include "src/name_registry.h"

#include <glm/vec3.hpp>

#include <vector>

namespace raylab::agent {

// A call's inputs in order, as the student's functions take them (float, int).
class ProbeInputs {
public:
    explicit ProbeInputs(const std::vector<double>& values) : m_numbers(values) {}
    double number() { return m_numbers.number(); }
    float real() { return float(number()); }
    int integer() { return int(number()); }
    glm::vec3 vec3() { return glm::vec3(m_numbers.vec3()); }

private:
    grader::protocol::NumberReader m_numbers;
};

// Appends a vector's three components to a probe's outputs.
void appendOutputs(std::vector<double>& out, const glm::vec3& v);

using ProbeFunction = std::vector<double> (*)(ProbeInputs inputs);

// Adds the function that answers `probe`; a probe answered twice is a std::logic_error naming both places.
void registerProbeFunction(const grader::protocol::ProbeSpec* probe, ProbeFunction function, SourcePlace where);

// Throws whatever the student's code throws (NotDoneYet included); std::invalid_argument when no
// function answers the probe.
std::vector<double> callProbe(const grader::protocol::Call& call);

struct ProbeRegistrar {
    ProbeRegistrar(const grader::protocol::ProbeSpec* probe, ProbeFunction function,
                   SourcePlace where = SourcePlace::here()) {
        registerProbeFunction(probe, function, where);
    }
};

} // namespace raylab::agent

#define RAYLAB_REGISTER_PROBE(probe, function) RAYLAB_REGISTRAR(::raylab::agent::ProbeRegistrar)((probe), (function))
