// Reference solution: full-sweep SAH (docs/a2-sah.md#full-sweep).
#include "sah_cost.h"

#include <algorithm>
#include <limits>
#include <vector>

namespace rtlab {

uint32_t splitSahSweep(std::span<BuildPrimitive> prims, const NodeInfo& node, const BvhOptions& options) {
    const auto n = static_cast<uint32_t>(prims.size());
    // rightBounds[k] = bounds of prims[k..n) in the current order. Reused across nodes, so the
    // build does not allocate per node.
    thread_local std::vector<Bounds3f> rightBounds;
    if (rightBounds.size() < n) rightBounds.resize(n);

    double bestArea = std::numeric_limits<double>::infinity();
    int bestAxis = -1, sortedAxis = -1;
    uint32_t bestLeft = 0;
    Vec3 centroidExtent = node.centroidBounds.diagonal();
    int longest = node.centroidBounds.longestAxis();
    for (int axis = 0; axis < 3; ++axis) {
        if (options.allAxes ? !(centroidExtent[axis] > 0) : axis != longest) continue;
        // A child often comes sorted already: by its parent's axis, when that is its longest
        // too. Checking costs one pass; sorting again would cost n log n comparisons.
        if (!std::is_sorted(prims.begin(), prims.end(), CentroidOrder{axis}))
            std::sort(prims.begin(), prims.end(), CentroidOrder{axis});
        sortedAxis = axis;

        rightBounds[n - 1] = prims[n - 1].bounds;
        for (uint32_t k = n - 1; k-- > 1;) rightBounds[k] = unionOf(rightBounds[k + 1], prims[k].bounds);
        Bounds3f leftBounds;
        for (uint32_t k = 1; k < n; ++k) {  // split k: prims[0..k) left, prims[k..n) right
            leftBounds.extend(prims[k - 1].bounds);
            double area = weightedChildArea(leftBounds, k, rightBounds[k], n - k);
            if (area < bestArea) {  // strict: ties keep the lower axis, then the lower k
                bestArea = area;
                bestAxis = axis;
                bestLeft = k;
            }
        }
    }
    // No finite cost (non-finite primitive bounds) or the leaf is at least as cheap.
    if (bestAxis < 0 || !splitBeatsLeaf(bestArea, n, node, options)) return 0;
    if (sortedAxis != bestAxis) std::sort(prims.begin(), prims.end(), CentroidOrder{bestAxis});
    return bestLeft;
}

}  // namespace rtlab
