// Assignment a2, part 1: full-sweep SAH.          Guide: docs/a2-sah.md#full-sweep
//
// Contract (framework/interface/a2_sah.h):
//   Called with n >= 2 primitives and a non-zero centroid extent. For each axis to try (the
//   longest centroid axis, or every axis with a non-zero centroid extent if options.allAxes),
//   order prims by CentroidOrder{axis} and evaluate every split k = 1 .. n-1 (prims[0..k)
//   left, prims[k..n) right):
//       C(k) = 1 + (S(left) * k + S(right) * (n - k)) / S(node)      (S = surface area)
//   Keep the cheapest; on equal cost keep the lower axis, then the lower k. Then:
//     n > options.maxLeaf                      -> split: prims ordered on the chosen axis, return k
//     n <= options.maxLeaf and C(k) < n        -> split the same way
//     otherwise                                -> return 0 (leaf)
//
// Hints:
//   * O(n) per axis after sorting: first sweep from the right storing the bounds of
//     prims[k..n) for every k, then sweep from the left growing the left bounds.
//   * Sorting again at the end is only needed if the chosen axis is not the last one sorted.
//   * Compute areas and costs in double (docs/a2-sah.md#cost): float overflows near 1e19.
#include "framework/core/error.h"
#include "framework/interface/a2_sah.h"

namespace rtlab {

uint32_t splitSahSweep(std::span<BuildPrimitive> prims, const NodeInfo& node, const BvhOptions& options) {
    (void)prims, (void)node, (void)options;
    throw NotImplemented("a2 splitSahSweep (assignments/a2_sah/sah_sweep.cpp)");
}

}  // namespace rtlab
