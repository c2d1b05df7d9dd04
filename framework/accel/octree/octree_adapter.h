// a4's octree as the framework drives it: built over a primitive set and queried, each through
// the student's functions. The accelerator (octree_accelerator.h: render, hits, the bench) and
// the grader's worker (grader/a4_octree/worker/octree_tasks.cpp) both call these, so what is
// graded is what renders.
#pragma once

#include "framework/accel/primitive_set.h"
#include "framework/interface/octree.h"
#include "framework/interface/traversal.h"

namespace rtlab {

struct OctreeAdapter {
    // a4's buildOctree over every primitive's box and every triangle.
    static Octree build(const PrimitiveSet& primitives, const OctreeOptions& options);
    // Closest hit in (ray.tMin, hit.t]: a4's intersectOctree.
    static bool intersect(const Octree& octree, Traversal& traversal, Hit& hit);
    // Any hit: a4's occludedOctree.
    static bool occluded(const Octree& octree, Traversal& traversal);
};

}  // namespace rtlab
