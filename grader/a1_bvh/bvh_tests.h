// The tests every BVH build configuration gets (docs/grading.md): the generic structure tests
// of structure_tests.h with the BVH plugged in: structure invariants, the SAH cost against the
// reference, hit sets of the ordered, recursive and any-hit traversals against the oracle,
// efficiency, the order leaves are visited in, and the degenerate inputs of the stress
// catalogue.
#pragma once

#include "framework/interface/bvh.h"
#include "grader/kit/accelerator_checks.h"
#include "grader/engine/test_group.h"

#include <memory>
#include <string>
#include <vector>

namespace rtlab::grader {

struct BvhConfig {
    std::string assignment;  // "a1"
    std::string label;       // "median", "buckets-12": names the tests and the reference entries
    BvhOptions options;
    std::string buildStub;   // named in verdicts: "a1 buildBvh + a1 splitMedian"
    bool exactSah = false;   // median, middle, equal counts: the reference tree exactly
    bool recursive = false;  // also grade intersectBvhRecursive
    bool visitOrder = false; // also grade the order intersectBvh visits leaves in (visit_order.h)
};

// Relative tolerance of the SAH cost for the SAH builders, and for the builders whose tree is
// pinned exactly (the same tree gives the same cost to the last bits; 1e-12 absorbs nothing
// but the reference file's decimal round trip).
inline constexpr double kSahTolerance = 1e-4;
inline constexpr double kExactSahTolerance = 1e-12;

std::vector<TestGroup> bvhConfigGroups(const BvhConfig& config, GradingContext& context);

}  // namespace rtlab::grader
