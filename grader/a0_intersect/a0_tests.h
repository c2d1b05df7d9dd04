// Assignment a0's graded tests: the intersection tests (docs/a0-intersect.md), as the test groups
// the grading session runs in sandboxed workers (docs/grading.md, "What is tested"). The registry
// (grader/assignment_registry.cpp) lists it.
#pragma once

#include "grader/engine/stub_table.h"
#include "grader/engine/test_group.h"

#include <vector>

namespace rtlab::grader {

std::vector<TestGroup> a0Groups(GradingContext& context);
// The stubs of assignments/a0_intersect/, as they name themselves (a0_stubs.cpp).
const StubTable& a0Stubs();

}  // namespace rtlab::grader
