#include "grader/judge/time_budget.h"

#include <algorithm>

namespace raylab::grader {

double labBudgetSeconds(const ReferenceSet& references, int lab, const TimeBudget& budget) {
    double reference = 0.;
    for (const FigureReference& f : references.figures)
        if (f.lab == lab) reference += f.renderSeconds;
    return std::max(budget.floorSeconds, budget.factor * reference);
}

} // namespace raylab::grader
