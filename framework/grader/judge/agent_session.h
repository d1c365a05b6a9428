#pragma once
// One agent's session: the items of its labs sent over as many runs as it takes until every one is
// answered. An item whose run ended without its answer (a crash, an endless loop, an exit) fails
// with the reason and is not sent again, so one bad function costs only itself.

#include "grader/judge/answers.h"
#include "grader/judge/grade.h"

#include <string>

namespace raylab::grader {

// "all" or "labN": names the folders of an agent's runs and of its pictures.
std::string agentName(const AgentPlan& plan);

// Runs the agent until each of its items is answered or failed. `withChecks`: false sends the
// figures only.
Reported runUntilDone(const GradeSetup& setup, const AgentPlan& plan, bool withChecks = true);

} // namespace raylab::grader
