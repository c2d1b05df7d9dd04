// Reference solution: the best plane of a node in one sweep per axis, and the side of a plane a
// primitive goes to (docs/a5-kdtree.md#the-best-plane).
#include "framework/interface/a5_kdtree.h"

namespace rtlab {

KdSplit kdBestSplit(const Bounds3f& node, const KdNodeEvents& events, uint32_t primCount, const KdCosts& costs) {
    KdSplit best;
    auto consider = [&](int axis, float position, KdSide planarSide, uint32_t nBelow, uint32_t nAbove) {
        double cost = kdSahCost(node, axis, position, nBelow, nAbove, costs);
        // Strictly cheaper only: the first of equal costs in sweep order stays.
        if (cost < best.cost) best = KdSplit{axis, position, planarSide, cost, nBelow, nAbove};
    };
    for (int axis = 0; axis < 3; ++axis) {
        std::span<const KdEvent> list = events[axis];
        // Before position p: nLess boxes start (or lie) below p; nMore boxes end above it.
        uint32_t nLess = 0, nMore = primCount;
        for (size_t i = 0; i < list.size();) {
            float p = list[i].position;
            // The events at p, in their order: Ends, then Planars, then Starts.
            uint32_t ends = 0, planars = 0, starts = 0;
            for (; i < list.size() && list[i].position == p && list[i].type == KdEventType::End; ++i) ++ends;
            for (; i < list.size() && list[i].position == p && list[i].type == KdEventType::Planar; ++i) ++planars;
            for (; i < list.size() && list[i].position == p && list[i].type == KdEventType::Start; ++i) ++starts;
            // Boxes ending at p touch the plane from below and boxes lying in it are in neither
            // count: neither lies above p.
            nMore -= ends + planars;
            // A plane on the node's face would leave one child with the whole node.
            if (node.lower[axis] < p && p < node.upper[axis]) {
                consider(axis, p, KdSide::Below, nLess + planars, nMore);
                // Without primitives in the plane both sides score the same: below stays.
                if (planars > 0) consider(axis, p, KdSide::Above, nLess, nMore + planars);
            }
            nLess += planars + starts;
        }
    }
    return best;
}

KdSide kdClassify(const Bounds3f& box, int axis, float position, KdSide planarSide) {
    float lower = box.lower[axis], upper = box.upper[axis];
    // Coordinates decide, never the event that was chosen: a box touching the plane goes to the
    // side it lies on, and only a box lying in the plane needs the pinned side.
    bool inPlane = lower == position && upper == position;
    bool below = lower < position || (inPlane && planarSide == KdSide::Below);
    bool above = upper > position || (inPlane && planarSide == KdSide::Above);
    return below && above ? KdSide::Both : below ? KdSide::Below : KdSide::Above;
}

}  // namespace rtlab
