// The SAH arithmetic both reference split functions share (docs/a2-sah.md#cost). Costs are
// evaluated in double: float surface areas overflow for extents near 1e19 and lose the
// difference between nearly equal splits.
#pragma once

#include "framework/interface/a2_sah.h"

namespace rtlab {

inline double surfaceAreaOf(const Bounds3f& b) {
    if (b.isEmpty()) return 0.0;
    DVec3 d = DVec3(b.upper) - DVec3(b.lower);
    return 2.0 * (d.x * d.y + d.y * d.z + d.z * d.x);
}

// S(A) N_A + S(B) N_B: what the candidate splits of one node are ranked by. It orders them
// exactly as C does, without dividing by S(N), which may be 0.
inline double weightedChildArea(const Bounds3f& a, uint32_t countA, const Bounds3f& b, uint32_t countB) {
    return surfaceAreaOf(a) * countA + surfaceAreaOf(b) * countB;
}

// C = C_trav + (S(A) N_A + S(B) N_B) / S(N) * C_isect.
inline double sahSplitCost(double weightedArea, const NodeInfo& node) {
    return kSahTraversalCost + weightedArea / surfaceAreaOf(node.bounds) * kSahIntersectionCost;
}

// The pinned leaf rule: more than maxLeaf primitives are always split; at most maxLeaf only
// when the split is strictly cheaper than the leaf, N C_isect. A node of zero area (its
// primitives on one line) gives a NaN cost, which is never cheaper.
inline bool splitBeatsLeaf(double weightedArea, uint32_t n, const NodeInfo& node, const BvhOptions& options) {
    if (n > static_cast<uint32_t>(options.maxLeaf)) return true;
    return sahSplitCost(weightedArea, node) < n * kSahIntersectionCost;
}

}  // namespace rtlab
