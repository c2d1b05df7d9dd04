// Assignment a5, part 4: when to stop.             Guide: docs/a5-kdtree.md#when-to-stop
//
// Contract (framework/interface/a5_kdtree.h):
//   * kdMaxDepth(N) = lround(8 + 1.3 * k) in double, k = floor(log2 N) = the index of N's highest
//     set bit; 8 for N <= 1; never more than kKdMaxDepthLimit.
//   * kdDecideNode, in this order (leafCost = options.costs.intersection * primCount):
//       1. primCount <= options.maxPrims or depth >= options.maxDepth  -> {leaf, badRefines}
//       2. !best.found()                                              -> {leaf, badRefines}
//       3. best.cost > leafCost: ++badRefines
//       4. (best.cost > 4 * leafCost && primCount < 16) || badRefines >= kKdMaxBadRefines -> leaf
//       5. otherwise not a leaf; return the badRefines after step 3 either way.
//
// Hints:
//   * std::bit_width(N) - 1 is floor(log2 N) for N >= 1 (<bit>); std::log2 of a double can round
//     up just below a power of two.
//   * 100 identical triangles have no plane strictly inside their node: rule 2 ends them.
#include "framework/core/error.h"
#include "framework/interface/a5_kdtree.h"

namespace rtlab {

int kdMaxDepth(size_t primCount) {
    (void)primCount;
    throw NotImplemented("a5 kdMaxDepth (assignments/a5_kdtree/kd_leaf.cpp)");
}

KdNodeDecision kdDecideNode(uint32_t primCount, int depth, const KdSplit& best, int badRefines, const KdTreeOptions& options) {
    (void)primCount, (void)depth, (void)best, (void)badRefines, (void)options;
    throw NotImplemented("a5 kdDecideNode (assignments/a5_kdtree/kd_leaf.cpp)");
}

}  // namespace rtlab
