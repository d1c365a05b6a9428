#pragma once
// The lab an agent was built for: raylab-agent-labN answers lab N's checks and figures only, so that
// a student's code that starts it in place of another lab's agent gets nothing from it.

namespace raylab::agent {

// 0: an agent of every lab (raylab-agent, the reference's, the tests'). Compiled into each agent on
// its own (agent_lab.cpp, with RAYLAB_AGENT_LAB from raylab_add_agent's LAB, framework/grader/CMakeLists.txt).
extern const int kAgentLab;

} // namespace raylab::agent
