// Assignment a2 (docs/a2-sah.md): split BVH nodes with the surface area heuristic.
// Implemented in assignments/a2_sah/ (yours) and solutions/a2_sah/ (reference).
//
// Cost of splitting node N into A and B (C_trav = C_isect = 1, kSahTraversalCost and
// kSahIntersectionCost):
//     C = C_trav + S(A)/S(N) * N_A * C_isect + S(B)/S(N) * N_B * C_isect
// and the cost of a leaf is N * C_isect. Pinned rules (docs/conventions.md):
//  * axis: the longest axis of the centroid bounds, or each of x, y, z if options.allAxes;
//  * ties: the lower axis wins, then the lower split index;
//  * a node with more than options.maxLeaf primitives is always split (at the cheapest split);
//    one with at most maxLeaf is split only when the cheapest split costs less than the leaf.
// Both functions reorder prims so the left part comes first and return its size, or 0 for
// a leaf. They are only called with n >= 2 and a non-zero centroid extent.
#pragma once

#include "framework/interface/bvh.h"

namespace rtlab {

inline constexpr float kSahTraversalCost = 1.0f;
inline constexpr float kSahIntersectionCost = 1.0f;

// Full sweep: order by (centroid[axis], index) and evaluate all n-1 splits between
// neighbours, with prefix and suffix bounds so the sweep is O(n) after sorting.
uint32_t splitSahSweep(std::span<BuildPrimitive> prims, const NodeInfo& node, const BvhOptions& options);

// Buckets: B = options.buckets equal-width buckets over the centroid bounds on the axis,
// bucket(c) = min(B-1, floor(B * (c - cmin) / (cmax - cmin))); evaluate the B-1 planes
// between buckets; left = the primitives in buckets below the chosen plane.
uint32_t splitSahBuckets(std::span<BuildPrimitive> prims, const NodeInfo& node, const BvhOptions& options);

}  // namespace rtlab
