// Assignment a5, part 3: the best plane of a node. Guide: docs/a5-kdtree.md#the-best-plane
//
// Contract (framework/interface/a5_kdtree.h):
//   * kdBestSplit: for axis x, y, z, sweep events[axis] once, position by position. Keep nLess
//     (boxes with lower < p; 0 at the start) and nMore (boxes with upper > p; primCount at the
//     start). At position p, with the numbers of Ends, Planars and Starts there:
//        nMore -= ends + planars;
//        if node.lower[axis] < p < node.upper[axis]: score kdSahCost with
//            (nLess + planars, nMore), planarSide Below, then (nLess, nMore + planars), Above;
//        nLess += planars + starts;
//     Keep a split only when its cost is strictly lower than the best so far. No candidate:
//     return KdSplit{}.
//   * kdClassify: below = lower < position || (lower == upper == position && planarSide == Below);
//     above = upper > position || (lower == upper == position && planarSide == Above); Both when
//     both hold.
//
// Hints:
//   * The events of one position are together, Ends first, then Planars, then Starts: count
//     each kind with a loop that stops when the position or the type changes.
//   * A box that ends exactly at p touches the plane from below: it is below only, never above.
#include "framework/core/error.h"
#include "framework/interface/a5_kdtree.h"

namespace rtlab {

KdSplit kdBestSplit(const Bounds3f& node, const KdNodeEvents& events, uint32_t primCount, const KdCosts& costs) {
    (void)node, (void)events, (void)primCount, (void)costs;
    throw NotImplemented("a5 kdBestSplit (assignments/a5_kdtree/kd_split.cpp)");
}

KdSide kdClassify(const Bounds3f& box, int axis, float position, KdSide planarSide) {
    (void)box, (void)axis, (void)position, (void)planarSide;
    throw NotImplemented("a5 kdClassify (assignments/a5_kdtree/kd_split.cpp)");
}

}  // namespace rtlab
