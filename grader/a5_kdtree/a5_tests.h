// Assignment a5's graded tests: the KD-tree (docs/a5-kdtree.md), as the test groups the grading
// session runs in sandboxed workers (docs/grading.md, "What is tested"). The registry
// (grader/assignment_registry.cpp) lists it.
#pragma once

#include "grader/engine/stub_table.h"
#include "grader/engine/test_group.h"

#include <vector>

namespace rtlab::grader {

std::vector<TestGroup> a5Groups(GradingContext& context);
// The stubs of assignments/a5_kdtree/, as they name themselves (a5_stubs.cpp).
const StubTable& a5Stubs();

}  // namespace rtlab::grader
