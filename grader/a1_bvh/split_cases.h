// Unit cases for the split functions of a1 and a2 with hand-derived answers
// (docs/grading.md, "Split functions"): axis choice, ordering ties by primitive index, the
// middle split's fallback, SAH costs with exact ties (lower split index, then lower axis
// wins), the maxLeaf rule and the bucket clamp. All coordinates are dyadic, so every cost a
// float implementation computes is exact and ties are real ties.
#pragma once

#include "grader/a1_bvh/wire/bvh_inputs.h"

#include "framework/interface/bvh.h"
#include "grader/engine/test_group.h"

#include <string>
#include <vector>

namespace rtlab::grader {

using worker::SplitFunction;

struct SplitCase {
    std::string id;
    SplitFunction function;
    std::vector<Bounds3f> boxes;  // primitive i has index i and centroid = box centre
    BvhOptions options;
    uint32_t expectedLeftCount;   // 0: the function must make a leaf
    std::vector<uint32_t> expectedLeft;  // the primitive indices of the left part (any order)
    std::string derivation;       // the hand calculation, shown when the case fails
};

std::vector<SplitCase> a1SplitCases();
std::vector<SplitCase> a2SplitCases();

// One group: a phase per function the cases use, and a test named testName.
TestGroup splitCaseGroup(const std::string& assignment, const std::string& testName, std::vector<SplitCase> cases);

}  // namespace rtlab::grader
