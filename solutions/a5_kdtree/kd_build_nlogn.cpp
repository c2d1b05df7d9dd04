// Reference solution beyond the lecture: the same KD-tree in O(N log N), as Wald and Havran
// (2006) build it (docs/a5-kdtree.md#building-in-on-log-n). The events are sorted once, at the
// root; a split hands every sorted list down in order, so no node sorts again.
#include "kd_tree_parts.h"

namespace rtlab {

namespace {

using AxisEvents = std::array<std::vector<KdEvent>, 3>;

struct Builder {
    std::span<const Bounds3f> primBounds;
    const KdTreeOptions& options;  // maxDepth resolved
    KdTree& tree;
    std::vector<KdSide> sideOf;    // per primitive id: its side of the current node's plane

    void build(const Bounds3f& box, const std::vector<uint32_t>& prims, AxisEvents events, int depth, int badRefines) {
        KdSplit best;
        KdNodeDecision decision = kd::decide(options, prims.size(), depth, badRefines, &best, [&] {
            return kdBestSplit(box, {events[0], events[1], events[2]}, uint32_t(prims.size()), options.costs);
        });
        if (decision.leaf) {
            kd::appendLeaf(tree, prims);
            return;
        }
        kd::Children children = kd::classify(prims, primBounds, best, &sideOf);
        // A sub-sequence of a sorted list is sorted: each child's events are exactly the ones a
        // sort of its own primitives would give, in the same order. Events carry their primitive's
        // full box (no clipping), so a primitive in both children brings the same events to both.
        AxisEvents below, above;
        for (int axis = 0; axis < 3; ++axis) {
            // Sized first: growing lists of millions of events would copy each several times.
            size_t nBelow = 0, nAbove = 0;
            for (const KdEvent& e : events[axis]) {
                nBelow += sideOf[e.prim] != KdSide::Above;
                nAbove += sideOf[e.prim] != KdSide::Below;
            }
            below[axis].reserve(nBelow);
            above[axis].reserve(nAbove);
            for (const KdEvent& e : events[axis]) {
                if (sideOf[e.prim] != KdSide::Above) below[axis].push_back(e);
                if (sideOf[e.prim] != KdSide::Below) above[axis].push_back(e);
            }
            events[axis] = {};  // the parent's lists are not needed any more
        }
        kd::appendInterior(tree, best, [&](KdSide side) {
            bool isBelow = side == KdSide::Below;
            build(kd::childBox(box, best, side), isBelow ? children.below : children.above, std::move(isBelow ? below : above), depth + 1,
                  decision.badRefines);
        });
    }
};

}  // namespace

KdTree buildKdTreeNlogN(std::span<const Bounds3f> primBounds, const KdTreeOptions& options) {
    kd::Root root = kd::rootOf(primBounds, options);
    if (root.prims.empty()) return std::move(root.tree);
    AxisEvents events;
    for (int axis = 0; axis < 3; ++axis) events[axis] = kdSortedEvents(root.prims, primBounds, axis);
    Builder builder{primBounds, root.options, root.tree, std::vector<KdSide>(primBounds.size())};
    builder.build(root.tree.bounds, root.prims, std::move(events), 0, 0);
    return std::move(root.tree);
}

}  // namespace rtlab
