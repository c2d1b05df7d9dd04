// Assignment a1's graded tests: the BVH builds and traversals (docs/a1-bvh.md), as the test groups
// the grading session runs in sandboxed workers (docs/grading.md, "What is tested"). The registry
// (grader/assignment_registry.cpp) lists it.
#pragma once

#include "grader/engine/stub_table.h"
#include "grader/engine/test_group.h"

#include <vector>

namespace rtlab::grader {

std::vector<TestGroup> a1Groups(GradingContext& context);
// The stubs of assignments/a1_bvh/, as they name themselves (a1_stubs.cpp).
const StubTable& a1Stubs();

}  // namespace rtlab::grader
