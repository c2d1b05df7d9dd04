// Assignment a1, part 1: split heuristics.        Guide: docs/a1-bvh.md#split-heuristics
//
// Contract (framework/interface/a1_bvh.h):
//   Each function reorders prims so the left child's primitives come first and returns how
//   many there are, k with 0 < k < prims.size(). They are called with at least two
//   primitives whose centroids are not all equal.
//   * splitMedian:      axis = node.bounds.longestAxis(); k = n / 2 in centroid order.
//   * splitEqualCounts: axis = node.centroidBounds.longestAxis(); k = n / 2 in centroid order.
//   * splitMiddle:      axis = node.centroidBounds.longestAxis(); mid = (lower + upper) / 2 of
//                       the centroid bounds on that axis; left = centroid[axis] < mid. If one
//                       side is empty, return splitEqualCounts(prims, node) instead.
//   "Centroid order" is CentroidOrder{axis} (framework/interface/bvh.h): by centroid[axis],
//   ties by primitive index, so everybody's tree has the same children.
//
// Hints:
//   * The median needs no full sort: std::nth_element(begin, begin + n/2, end, order) puts
//     exactly the right n/2 primitives in front, in O(n).
//   * std::partition does the middle split in one pass.
#include "framework/core/error.h"
#include "framework/interface/a1_bvh.h"

namespace rtlab {

uint32_t splitMedian(std::span<BuildPrimitive> prims, const NodeInfo& node) {
    (void)prims, (void)node;
    throw NotImplemented("a1 splitMedian (assignments/a1_bvh/bvh_splits.cpp)");
}

uint32_t splitEqualCounts(std::span<BuildPrimitive> prims, const NodeInfo& node) {
    (void)prims, (void)node;
    throw NotImplemented("a1 splitEqualCounts (assignments/a1_bvh/bvh_splits.cpp)");
}

uint32_t splitMiddle(std::span<BuildPrimitive> prims, const NodeInfo& node) {
    (void)prims, (void)node;
    throw NotImplemented("a1 splitMiddle (assignments/a1_bvh/bvh_splits.cpp)");
}

}  // namespace rtlab
