// Reference solution: the depth limit and the leaf rule, pbrt's (docs/a5-kdtree.md#when-to-stop).
#include "framework/interface/a5_kdtree.h"

#include <algorithm>
#include <bit>
#include <cmath>

namespace rtlab {

int kdMaxDepth(size_t primCount) {
    // floor(log2 N) exactly, from the highest set bit: std::log2 of a double may round up just
    // below a power of two.
    int log2Floor = primCount <= 1 ? 0 : int(std::bit_width(primCount)) - 1;
    // No traversal stack holds more levels (reached from N = 2^44 on).
    return std::min(kKdMaxDepthLimit, int(std::lround(8.0 + 1.3 * log2Floor)));
}

KdNodeDecision kdDecideNode(uint32_t primCount, int depth, const KdSplit& best, int badRefines, const KdTreeOptions& options) {
    if (primCount <= options.maxPrims || depth >= options.maxDepth) return {true, badRefines};
    // Identical boxes, or all of them spanning the node: no plane lies strictly inside.
    if (!best.found()) return {true, badRefines};
    double leafCost = options.costs.intersection * primCount;
    // A split that costs more than the leaf may still pay off further down, so it is allowed a
    // few times on a path, never forever.
    if (best.cost > leafCost) ++badRefines;
    bool hopeless = best.cost > 4.0 * leafCost && primCount < 16;
    return {hopeless || badRefines >= kKdMaxBadRefines, badRefines};
}

}  // namespace rtlab
