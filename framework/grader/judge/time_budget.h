#pragma once
// A lab's wall-clock budget (docs/grading.md, "Time budgets"): what all of its items may take, over
// every run of its agent, a stopped or sleeping agent included. Made from the reference's own time on
// the lab's figures (recorded by `raylab references`), so that one student cannot hold a class for
// hours with answers that each come just under the per-item limit.

#include "grader/judge/references.h"

namespace raylab::grader {

struct TimeBudget {
    double factor = 20.;       // times the reference's time on the lab's figures
    double floorSeconds = 20.; // never less: an agent's start, the checks, a loaded or slower machine
};

// Lab `lab`'s budget in seconds.
double labBudgetSeconds(const ReferenceSet& references, int lab, const TimeBudget& budget);

} // namespace raylab::grader
