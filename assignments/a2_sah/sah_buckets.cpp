// Assignment a2, part 2: bucketed SAH.            Guide: docs/a2-sah.md#buckets
//
// Contract (framework/interface/a2_sah.h):
//   Called with n >= 2 primitives and a non-zero centroid extent. B = options.buckets (2..32).
//   For each axis to try (the longest centroid axis, or every axis with a non-zero centroid
//   extent if options.allAxes), with cmin, cmax the centroid bounds on that axis:
//       bucket(c) = min(B - 1, floor(B * (c - cmin) / (cmax - cmin)))    (float, this order)
//   Count the primitives and grow the bounds of each bucket, then evaluate the B-1 planes:
//   plane p puts buckets 0..p left and p+1..B-1 right, skipping planes with an empty side,
//       C(p) = 1 + (S(left) * N_left + S(right) * N_right) / S(node)
//   Keep the cheapest; on equal cost the lower axis, then the lower p. Then:
//     n > options.maxLeaf or C(p) < n   -> move the primitives with bucket <= p to the front
//                                          and return how many there are
//     otherwise                          -> return 0 (leaf)
//
// Hints:
//   * Use the same bucket function for binning and for partitioning.
//   * Without the min(), the largest centroid lands in bucket B: out of bounds.
//   * Prefix and suffix sweeps over the buckets make the plane loop O(B).
//   * Compute areas and costs in double (docs/a2-sah.md#cost).
#include "framework/core/error.h"
#include "framework/interface/a2_sah.h"

namespace rtlab {

uint32_t splitSahBuckets(std::span<BuildPrimitive> prims, const NodeInfo& node, const BvhOptions& options) {
    (void)prims, (void)node, (void)options;
    throw NotImplemented("a2 splitSahBuckets (assignments/a2_sah/sah_buckets.cpp)");
}

}  // namespace rtlab
