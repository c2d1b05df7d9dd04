// Assignment a0's graded tests: the intersection tests (docs/a0-intersect.md), as the test groups the grading session runs in
// sandboxed workers (docs/grading.md, "What is tested"). The registry
// (grader/assignment_registry.cpp) lists it.
#pragma once

#include "grader/engine/test_group.h"

#include <vector>

namespace rtlab::grader {

std::vector<TestGroup> a0Groups(GradingContext& context);

}  // namespace rtlab::grader
