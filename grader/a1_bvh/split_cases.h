// Unit cases for the split functions of a1 and a2 with hand-derived answers
// (docs/grading.md, "Split functions"): axis choice, ordering ties by primitive index, the
// middle split's fallback, SAH costs with exact ties (lower split index, then lower axis
// wins), the maxLeaf rule and the bucket clamp. All coordinates are dyadic, so every cost a
// float implementation computes is exact and ties are real ties.
#pragma once

#include "grader/a1_bvh/wire/bvh_inputs.h"

#include "framework/interface/bvh.h"
#include "grader/engine/stub_table.h"
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

// The shorthands cases are written in: a box, a cube of side s at (x, y, z), split options.
inline Bounds3f caseBox(Vec3 lo, Vec3 hi) { return Bounds3f(lo, hi); }
inline Bounds3f cube(float x, float y, float z, float s) { return caseBox({x, y, z}, {x + s, y + s, z + s}); }
BvhOptions splitOptions(int maxLeaf, int buckets = 12, bool allAxes = false);

std::vector<SplitCase> a1SplitCases();

// One group of the assignment whose stubs are `stubs`: the functions its cases call (named from
// the table), and a test named testName.
TestGroup splitCaseGroup(const StubTable& stubs, const std::string& testName, std::vector<SplitCase> cases);

}  // namespace rtlab::grader
