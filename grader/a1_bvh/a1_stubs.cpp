#include "grader/a1_bvh/a1_tests.h"

namespace rtlab::grader {

const StubTable& a1Stubs() {
    static const StubTable table{"a1", "a1_bvh", {
        {"bvh_build.cpp", {"buildBvh"}},
        {"bvh_splits.cpp", {"splitMedian", "splitEqualCounts", "splitMiddle"}},
        {"bvh_traverse.cpp", {"intersectBvhRecursive", "intersectBvh", "occludedBvh"}},
    }};
    return table;
}

}  // namespace rtlab::grader
