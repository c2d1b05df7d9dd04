// Assignment a5, part 5: building the tree.        Guide: docs/a5-kdtree.md#building
//
// Contract (framework/interface/a5_kdtree.h, framework/interface/kdtree.h):
//   * Root: the primitives with isPlaceable(primBounds[i]), in increasing order; tree.bounds the
//     union of their boxes; tree.maxDepth = options.maxDepth > 0 ? options.maxDepth :
//     kdMaxDepth(their count). None: return the tree with no nodes.
//   * Node (box, prims, depth, badRefines), starting with (tree.bounds, root prims, 0, 0):
//       best = KdSplit{}; unless prims.size() <= maxPrims or depth >= tree.maxDepth:
//         events[a] = kdSortedEvents(prims, primBounds, a) for a = 0, 1, 2;
//         best = kdBestSplit(box, {events[0], events[1], events[2]}, prims.size(), options.costs);
//       decision = kdDecideNode(prims.size(), depth, best, badRefines, options with maxDepth =
//       tree.maxDepth). A leaf: nodes.push_back(KdNode::leaf(primIndices.size(), count)) and
//       append prims to primIndices. A split: each prim goes to the children
//       kdClassify(primBounds[prim], best.axis, best.position, best.planarSide) names (Both: to
//       both); push a placeholder node, build the below child (box with upper[axis] = position)
//       at depth + 1 with decision.badRefines, then set the placeholder to
//       KdNode::interior(axis, position, nodes.size()) and build the above child (lower[axis] =
//       position).
//
// Hints:
//   * Recursion is the simplest: the depth limit keeps it at most 64 deep.
//   * Keep the node's index, not a reference into tree.nodes: push_back may move the array.
//   * Going through prims in order keeps each child's list increasing, as the contract wants.
#include "framework/core/error.h"
#include "framework/interface/a5_kdtree.h"

namespace rtlab {

KdTree buildKdTree(std::span<const Bounds3f> primBounds, const KdTreeOptions& options) {
    (void)primBounds, (void)options;
    throw NotImplemented("a5 buildKdTree (assignments/a5_kdtree/kd_build.cpp)");
}

}  // namespace rtlab
