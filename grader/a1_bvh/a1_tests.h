// Assignment a1's graded tests: the BVH builds and traversals (docs/a1-bvh.md), as the test groups the grading session runs in
// sandboxed workers (docs/grading.md, "What is tested"). The registry
// (grader/assignment_registry.cpp) lists it.
#pragma once

#include "grader/engine/test_group.h"

#include <vector>

namespace rtlab::grader {

std::vector<TestGroup> a1Groups(GradingContext& context);

}  // namespace rtlab::grader
