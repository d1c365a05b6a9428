#pragma once
// Where a lab's failures come from: its own code, or the code of a failing lab it uses (lab 3's
// figures drawn through a lab 2 stub). The notes and the diagnoses blame only the labs to fix first.

#include "grader/judge/outcome.h"
#include "grader/lab_catalog.h"

namespace raylab::grader {

// Whether lab `lab` fails where no other failing lab can be the cause: a failed check or figure that
// uses no lab with failures. A lab whose every failure runs a failing lab's code is not worth fixing
// first.
bool hasOwnFailures(const LabCatalog& catalog, const GradeResult& result, int lab);

// "lab 3 uses lab 2, which has failures: fix lab 2 first", on each scored lab of `result`.
void addDependencyNotes(const LabCatalog& catalog, GradeResult& result);

} // namespace raylab::grader
