// The grader's own reading of an octree a child sent back (docs/a4-octree.md, "How the grader
// checks it"): the pinned layout and every rule of the build, checked against the grader's own
// boxes and overlap tests (grader/a4_octree/octree_oracle.h), without calling anything a student wrote.
#pragma once

#include "framework/interface/octree.h"
#include "framework/scene/scene.h"

#include <string>
#include <vector>

namespace rtlab::grader {

struct OctreeStructureReport {
    std::vector<std::string> problems;  // empty when every rule holds (the first few only)
    size_t problemCount = 0;
    size_t leaves = 0;
    int depth = 0;
    size_t unsure = 0;  // primitive-node pairs within rounding of touching: either answer passes
};

// Checks: the root is octreeRootBox of the placeable primitives; the nodes are in the pinned
// depth-first block order, every interior node's children a block of eight, every leaf's list
// where the running total puts it, nothing unreachable; each node's count lies between the
// primitives that surely and those that possibly overlap its box (given its parent's); each
// leaf lists in increasing order every primitive that surely overlaps it and only ones that
// possibly do; a node is split exactly when its count exceeds maxPrims above maxDepth and
// fewer than two children would receive all of it.
OctreeStructureReport checkOctreeStructure(const Octree& octree, const Scene& scene, const OctreeOptions& options);

}  // namespace rtlab::grader
