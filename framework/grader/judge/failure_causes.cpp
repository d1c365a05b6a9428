#include "grader/judge/failure_causes.h"

#include "src/messages.h"

#include <algorithm>

namespace raylab::grader {

namespace {

const LabOutcome* outcomeOf(const GradeResult& result, int lab) {
    for (const LabOutcome& l : result.labs)
        if (l.lab == lab) return &l;
    return nullptr;
}

bool hasFailures(const LabOutcome* lab) { return lab != nullptr && lab->points < lab->maxPoints; }

// Whether a failure of lab `lab` can come from lab `other`: a failed figure or check of `lab`
// whose description says it runs `other`'s code, while `other` has failures of its own.
bool failsThrough(const LabCatalog& catalog, const GradeResult& result, int lab, int other) {
    const LabDescription* description = catalog.lab(lab);
    if (description == nullptr || !hasFailures(outcomeOf(result, lab)) || !hasOwnFailures(catalog, result, other))
        return false;
    const auto uses = [other](const std::vector<int>& labs) { return std::find(labs.begin(), labs.end(), other) != labs.end(); };
    const bool figure = std::any_of(result.figures.begin(), result.figures.end(), [&](const FigureOutcome& f) {
        const LabFigure* item = description->figure(f.id);
        return f.lab == lab && !f.passed && item != nullptr && uses(item->uses);
    });
    const bool check = std::any_of(result.checks.begin(), result.checks.end(), [&](const CheckOutcome& c) {
        const LabCheck* item = description->check(c.name);
        return c.lab == lab && !c.passed && item != nullptr && uses(item->uses);
    });
    return figure || check;
}

} // namespace

bool hasOwnFailures(const LabCatalog& catalog, const GradeResult& result, int lab) {
    const LabDescription* description = catalog.lab(lab);
    // An item no description names counts as the lab's own.
    const auto own = [&](const auto* item) {
        return item == nullptr || std::none_of(item->uses.begin(), item->uses.end(), [&](int other) {
                   return hasFailures(outcomeOf(result, other));
               });
    };
    return std::any_of(result.figures.begin(), result.figures.end(),
                       [&](const FigureOutcome& f) {
                           return f.lab == lab && !f.passed && own(description ? description->figure(f.id) : nullptr);
                       }) ||
           std::any_of(result.checks.begin(), result.checks.end(), [&](const CheckOutcome& c) {
               return c.lab == lab && !c.passed && own(description ? description->check(c.name) : nullptr);
           });
}

// When two labs use each other and both fail through the other, only the later lab is told to fix
// the earlier one (the course's order).
void addDependencyNotes(const LabCatalog& catalog, GradeResult& result) {
    for (LabOutcome& lab : result.labs) {
        const LabDescription* description = catalog.lab(lab.lab);
        if (description == nullptr) continue;
        for (int other : description->uses) {
            if (!failsThrough(catalog, result, lab.lab, other)) continue;
            if (other > lab.lab && failsThrough(catalog, result, other, lab.lab)) continue; // said the other way
            lab.notes.push_back(
                tr("grade.uses_failing_lab", {{"lab", std::to_string(lab.lab)}, {"other", std::to_string(other)}}));
        }
    }
}

} // namespace raylab::grader
