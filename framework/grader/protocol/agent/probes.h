#pragma once
// The child's half of the function checks: each probe calls one student function with the inputs
// the parent drew and returns what came out, unjudged. A lab's grading folder answers its probes
// (framework/grader/labs/<lab>/probes.cpp) with functions of the types its probes.h declares
// (grader/protocol/probe.h):
//
//   RAYLAB_REGISTER_PROBE(grader::probes::intersect, intersectProbe);  // at namespace scope

#include "grader/protocol/probe.h"
#include "src/name_registry.h"

#include <functional>
#include <span>
#include <vector>

namespace raylab::agent {

// A call's inputs -> its answer's numbers.
using ProbeFunction = std::function<std::vector<double>(std::span<const double> inputs)>;

// Adds the function that answers `probe`; a probe answered twice is a std::logic_error naming both places.
void registerProbeFunction(const grader::protocol::ProbeSpec* probe, ProbeFunction function, SourcePlace where);

// Throws whatever the student's code throws (NotDoneYet included); std::invalid_argument when no
// function answers the probe.
std::vector<double> callProbe(const grader::protocol::Call& call);

struct ProbeRegistrar {
    template <class Answer, class... Inputs>
    ProbeRegistrar(const grader::protocol::Probe<Answer(Inputs...)>& probe, Answer (*function)(Inputs...),
                   SourcePlace where = SourcePlace::here()) {
        registerProbeFunction(
            probe.spec(),
            [function](std::span<const double> inputs) { return grader::protocol::Probe<Answer(Inputs...)>::answerWith(function, inputs); },
            where);
    }
};

} // namespace raylab::agent

#define RAYLAB_REGISTER_PROBE(probe, function) RAYLAB_REGISTRAR(::raylab::agent::ProbeRegistrar)((probe), (function))
