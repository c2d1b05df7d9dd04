// Assignment a3's graded tests: the uniform grid (docs/a3-grid.md), as the test groups the grading
// session runs in sandboxed workers (docs/grading.md, "What is tested"). The registry
// (grader/assignment_registry.cpp) lists it.
#pragma once

#include "grader/engine/stub_table.h"
#include "grader/engine/test_group.h"

#include <vector>

namespace rtlab::grader {

std::vector<TestGroup> a3Groups(GradingContext& context);
// The stubs of assignments/a3_grid/, as they name themselves (a3_stubs.cpp).
const StubTable& a3Stubs();

}  // namespace rtlab::grader
