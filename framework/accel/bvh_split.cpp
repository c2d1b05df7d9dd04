// The framework's part of BVH building: the rules shared by every split heuristic, and the
// dispatch to the heuristic the options name.
#include "framework/core/error.h"
#include "framework/interface/a1_bvh.h"
#include "framework/interface/a2_sah.h"

#include <string>

namespace rtlab {

NodeInfo describeNode(std::span<const BuildPrimitive> prims) {
    NodeInfo node;
    for (const BuildPrimitive& p : prims) {
        node.bounds.extend(p.bounds);
        node.centroidBounds.extend(p.centroid);
    }
    return node;
}

static bool isSah(SplitMethod method) {
    return method == SplitMethod::SahSweep || method == SplitMethod::SahBuckets;
}

uint32_t splitNode(std::span<BuildPrimitive> prims, const NodeInfo& node, int depth,
                   const BvhOptions& options) {
    const auto n = static_cast<uint32_t>(prims.size());
    bool zeroCentroidExtent = node.centroidBounds.lower == node.centroidBounds.upper;
    if (n <= 1 || zeroCentroidExtent || depth >= kMaxBvhDepth - 1) return 0;
    if (!isSah(options.method) && n <= static_cast<uint32_t>(options.maxLeaf)) return 0;

    uint32_t left = 0;
    switch (options.method) {
    case SplitMethod::Median: left = splitMedian(prims, node); break;
    case SplitMethod::Middle: left = splitMiddle(prims, node); break;
    case SplitMethod::EqualCounts: left = splitEqualCounts(prims, node); break;
    case SplitMethod::SahSweep: left = splitSahSweep(prims, node, options); break;
    case SplitMethod::SahBuckets: left = splitSahBuckets(prims, node, options); break;
    }
    // A split that leaves one side empty would recurse forever; say so instead.
    if (left >= n || (left == 0 && !isSah(options.method)))
        throw Error("split function returned " + std::to_string(left) + " of " + std::to_string(n) +
                    " primitives for the left child (must be between 1 and n-1)");
    return left;
}

}  // namespace rtlab
