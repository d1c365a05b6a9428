#pragma once
// The child's half of the function checks: each probe calls one student function with the inputs
// the parent drew and returns what came out, unjudged.

#include "grader/protocol/protocol.h"

#include <vector>

namespace raylab::agent {

// Throws whatever the student's code throws (NotDoneYet included).
std::vector<double> callProbe(const grader::protocol::Call& call);

} // namespace raylab::agent
