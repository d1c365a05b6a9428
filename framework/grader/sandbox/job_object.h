#pragma once
// Windows: an agent in a Job object (sandbox.h). No confinement of files or network (Windows has no
// bubblewrap: the grade says so), but the limits Linux sets: a wall-clock limit per item (the results
// file grows with each answer), the CPU time and memory of the job, its output files' sizes, and its
// whole tree killed at the end (KILL_ON_JOB_CLOSE: also when the grader dies).

#include "grader/sandbox/sandbox.h"

namespace raylab::grader::detail {

#ifdef _WIN32
// Runs `program args... --request-file F --report-file F` in `command.scratch`, within `limits`;
// its stdout and stderr go to stdout.txt and stderr.txt there. `command`'s paths are absolute.
AgentRun runInJob(const AgentCommand& command, const SandboxLimits& limits);
#endif

} // namespace raylab::grader::detail
