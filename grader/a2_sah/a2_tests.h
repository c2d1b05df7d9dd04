// Assignment a2's graded tests: the SAH builds (docs/a2-sah.md), as the test groups the grading
// session runs in sandboxed workers (docs/grading.md, "What is tested"). The registry
// (grader/assignment_registry.cpp) lists it.
#pragma once

#include "grader/engine/stub_table.h"
#include "grader/engine/test_group.h"

#include <vector>

namespace rtlab::grader {

std::vector<TestGroup> a2Groups(GradingContext& context);
// The stubs of assignments/a2_sah/, as they name themselves (a2_stubs.cpp).
const StubTable& a2Stubs();

}  // namespace rtlab::grader
