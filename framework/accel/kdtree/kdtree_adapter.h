// a5's KD-tree as the framework drives it: built over a primitive set and queried, each through
// the student's functions. The accelerator (kdtree_accelerator.h: render, hits, the bench) and
// the grader's worker (grader/a5_kdtree/worker/kdtree_tasks.cpp) both call these, so what is
// graded is what renders.
#pragma once

#include "framework/accel/primitive_set.h"
#include "framework/interface/kdtree.h"
#include "framework/interface/traversal.h"

namespace rtlab {

// Which of a5's builders makes the tree: buildKdTreeNlogN (events sorted once) or buildKdTree
// (every node sorts its own). Both must give the same tree.
enum class KdBuilder { NlogN, Sort };

struct KdTreeAdapter {
    static KdTree build(const PrimitiveSet& primitives, const KdTreeOptions& options, KdBuilder builder);
    // Closest hit in (ray.tMin, hit.t]: a5's intersectKdTree.
    static bool intersect(const KdTree& tree, Traversal& traversal, Hit& hit);
    // Any hit: a5's occludedKdTree.
    static bool occluded(const KdTree& tree, Traversal& traversal);
};

}  // namespace rtlab
