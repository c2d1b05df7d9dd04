// Reference solution: the lecture's split heuristics (docs/a1-bvh.md#split-heuristics).
#include "framework/interface/a1_bvh.h"

#include <algorithm>

namespace rtlab {

// Puts the n/2 primitives that come first in the pinned (centroid, index) order on the left.
// nth_element only partitions around the middle, which is all a split needs: O(n), not a sort.
static uint32_t splitInHalf(std::span<BuildPrimitive> prims, int axis) {
    auto half = static_cast<uint32_t>(prims.size() / 2);
    std::nth_element(prims.begin(), prims.begin() + half, prims.end(), CentroidOrder{axis});
    return half;
}

uint32_t splitMedian(std::span<BuildPrimitive> prims, const NodeInfo& node) {
    return splitInHalf(prims, node.bounds.longestAxis());
}

uint32_t splitEqualCounts(std::span<BuildPrimitive> prims, const NodeInfo& node) {
    return splitInHalf(prims, node.centroidBounds.longestAxis());
}

uint32_t splitMiddle(std::span<BuildPrimitive> prims, const NodeInfo& node) {
    int axis = node.centroidBounds.longestAxis();
    float mid = (node.centroidBounds.lower[axis] + node.centroidBounds.upper[axis]) / 2;
    auto left = std::partition(prims.begin(), prims.end(),
                               [&](const BuildPrimitive& p) { return p.centroid[axis] < mid; });
    auto k = static_cast<uint32_t>(left - prims.begin());
    // Huge overlapping boxes or the rounding of mid can leave one side empty.
    if (k == 0 || k == prims.size()) return splitEqualCounts(prims, node);
    return k;
}

}  // namespace rtlab
