// Assignment a6's graded tests: radiometry (docs/a6-radiometry.md), as the test groups the grading
// session runs in sandboxed workers (docs/grading.md, "What is tested"). The registry
// (grader/assignment_registry.cpp) lists it.
#pragma once

#include "grader/engine/stub_table.h"
#include "grader/engine/test_group.h"

#include <vector>

namespace rtlab::grader {

std::vector<TestGroup> a6Groups(GradingContext& context);
// The stubs of assignments/a6_radiometry/, as they name themselves (a6_stubs.cpp).
const StubTable& a6Stubs();

}  // namespace rtlab::grader
