// Assignment a1, part 2: building the BVH.        Guide: docs/a1-bvh.md#building
//
// Contract (framework/interface/a1_bvh.h, framework/interface/bvh.h):
//   Return a Bvh over prims (an empty Bvh for no primitives) whose nodes are in depth-first
//   order: nodes[0] is the root, an interior node's first child is the node right after it,
//   its `offset` is the index of its second child, and its primCount is 0. A leaf covers
//   primIndices[offset .. offset + primCount) and 1 <= primCount <= 65535.
//   For every node:
//     1. info = describeNode(its primitives)      -> node.bounds = info.bounds
//     2. k = splitNode(its primitives, info, depth, options)   (depth 0 at the root)
//     3. k == 0: a leaf. k > 0: the first k primitives (splitNode reordered them) form the
//        first child, the rest the second. Set node.axis =
//        maxComponentIndex(secondInfo.bounds.centre() - firstInfo.bounds.centre()).
//   If splitNode makes a leaf of more than 65535 primitives, split it with
//   splitEqualCounts instead.
//
// Hints:
//   * Keep the primitives in one array and give each node a range [begin, end) of it; a
//     leaf's primitives are then contiguous and primIndices[i] = prims[i].index at the end.
//   * Recursion is the simplest way: store the node, build the first child, then write the
//     second child's index into `offset`. Take the node's index, not a reference into the
//     vector: push_back may move the array.
//   * nodes.reserve(2 * n - 1) is enough for any tree with non-empty leaves.
#include "framework/core/error.h"
#include "framework/interface/a1_bvh.h"

namespace rtlab {

Bvh buildBvh(std::vector<BuildPrimitive> prims, const BvhOptions& options) {
    (void)prims, (void)options;
    throw NotImplemented("a1 buildBvh (assignments/a1_bvh/bvh_build.cpp)");
}

}  // namespace rtlab
