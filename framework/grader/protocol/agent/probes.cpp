#include "grader/protocol/agent/probes.h"

#include <map>
#include <stdexcept>
#include <string>

namespace raylab::agent {

namespace {

// Built on first use: the labs' probes register during static initialisation, in any order of files.
std::map<std::string, ProbeFunction>& functions() {
    static std::map<std::string, ProbeFunction> registered;
    return registered;
}

} // namespace

void appendOutputs(std::vector<double>& out, const glm::vec3& v) {
    out.insert(out.end(), {v.x, v.y, v.z});
}

void registerProbeFunction(const grader::protocol::ProbeSpec& probe, ProbeFunction function) {
    if (!functions().emplace(probe.name, function).second)
        throw std::logic_error("the probe '" + probe.name + "' is answered twice");
}

std::vector<double> callProbe(const grader::protocol::Call& call) {
    const auto it = functions().find(call.probe->name);
    if (it == functions().end()) throw std::invalid_argument("no function answers the probe " + call.probe->name);
    return it->second(ProbeInputs(call.inputs));
}

} // namespace raylab::agent
