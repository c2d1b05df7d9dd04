// The BVH of a1 and a2 as the framework drives it: built over a primitive set and queried, each
// through the student's functions. The accelerator (bvh_accelerator.h: render, hits, the bench)
// and the grader's worker (grader/a1_bvh/worker/bvh_tasks.cpp) both call these, so what is
// graded is what renders.
#pragma once

#include "framework/accel/primitive_set.h"
#include "framework/interface/bvh.h"
#include "framework/interface/traversal.h"

#include <vector>

namespace rtlab {

// What buildBvh needs to know of each primitive: bounds, centroid and id, in id order.
std::vector<BuildPrimitive> buildPrimitivesOf(const PrimitiveSet& primitives);

struct BvhAdapter {
    // a1's buildBvh with the split options.method names (a1's or a2's heuristics).
    static Bvh build(const PrimitiveSet& primitives, const BvhOptions& options);
    // Closest hit in (ray.tMin, hit.t]: a1's ordered traversal, intersectBvh.
    static bool intersect(const Bvh& bvh, Traversal& traversal, Hit& hit);
    // The same by the lecture's recursive pseudocode: a1's intersectBvhRecursive.
    static bool intersectRecursive(const Bvh& bvh, Traversal& traversal, Hit& hit);
    // Any hit: a1's occludedBvh.
    static bool occluded(const Bvh& bvh, Traversal& traversal);
};

}  // namespace rtlab
