// a5's optional BSP autopartition as the framework drives it: built over a primitive set and
// queried, each through the student's functions. The accelerator (bsp_accelerator.h) and the
// grader's worker (grader/a5_kdtree/worker/kdtree_tasks.cpp) both call these, so what is graded
// is what renders.
#pragma once

#include "framework/accel/primitive_set.h"
#include "framework/interface/bsp.h"
#include "framework/interface/traversal.h"

namespace rtlab {

struct BspAdapter {
    // a5's buildBspAutopartition over every triangle and every primitive's box.
    static BspTree build(const PrimitiveSet& primitives, const BspOptions& options);
    // Closest hit in (ray.tMin, hit.t]: a5's intersectBsp.
    static bool intersect(const BspTree& tree, Traversal& traversal, Hit& hit);
    // Any hit: a5's occludedBsp.
    static bool occluded(const BspTree& tree, Traversal& traversal);
};

}  // namespace rtlab
