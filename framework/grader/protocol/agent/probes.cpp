#include "grader/protocol/agent/probes.h"

#include "src/name_registry.h"

#include <stdexcept>

namespace raylab::agent {

namespace {

// Built on first use: the labs' probes register during static initialisation, in any order of files.
NameRegistry<ProbeFunction>& functions() {
    static NameRegistry<ProbeFunction> registry("probe answer");
    return registry;
}

} // namespace

void registerProbeFunction(const grader::protocol::ProbeSpec* probe, ProbeFunction function, SourcePlace where) {
    functions().add(probe->name, function, where);
}

std::vector<double> callProbe(const grader::protocol::Call& call) {
    const auto* function = functions().find(call.probe->name);
    if (function == nullptr) throw std::invalid_argument("no function answers the probe " + call.probe->name);
    return function->value(call.inputs);
}

} // namespace raylab::agent
