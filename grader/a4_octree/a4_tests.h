// Assignment a4's graded tests: the octree (docs/a4-octree.md), as the test groups the grading
// session runs in sandboxed workers (docs/grading.md, "What is tested"). The registry
// (grader/assignment_registry.cpp) lists it.
#pragma once

#include "grader/engine/stub_table.h"
#include "grader/engine/test_group.h"

#include <vector>

namespace rtlab::grader {

std::vector<TestGroup> a4Groups(GradingContext& context);
// The stubs of assignments/a4_octree/, as they name themselves (a4_stubs.cpp).
const StubTable& a4Stubs();

}  // namespace rtlab::grader
