// Which lab this agent answers (agent_lab.h): compiled for each agent with its RAYLAB_AGENT_LAB.
#include "grader/protocol/agent/agent_lab.h"

namespace raylab::agent {

const int kAgentLab = RAYLAB_AGENT_LAB;

} // namespace raylab::agent
