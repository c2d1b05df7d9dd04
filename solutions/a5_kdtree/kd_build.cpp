// Reference solution: the KD-tree built node by node, each node sorting its own events
// (docs/a5-kdtree.md#building). Simple and O(N log^2 N); kd_build_nlogn.cpp builds the same tree
// without sorting again.
#include "kd_tree_parts.h"

namespace rtlab {

namespace {

struct Builder {
    std::span<const Bounds3f> primBounds;
    const KdTreeOptions& options;  // maxDepth resolved
    KdTree& tree;

    void build(const Bounds3f& box, const std::vector<uint32_t>& prims, int depth, int badRefines) {
        KdSplit best;
        KdNodeDecision decision = kd::decide(options, prims.size(), depth, badRefines, &best, [&] {
            std::array<std::vector<KdEvent>, 3> events;
            for (int axis = 0; axis < 3; ++axis) events[axis] = kdSortedEvents(prims, primBounds, axis);
            return kdBestSplit(box, {events[0], events[1], events[2]}, uint32_t(prims.size()), options.costs);
        });
        if (decision.leaf) {
            kd::appendLeaf(tree, prims);
            return;
        }
        kd::Children children = kd::classify(prims, primBounds, best);
        kd::appendInterior(tree, best, [&](KdSide side) {
            build(kd::childBox(box, best, side), side == KdSide::Below ? children.below : children.above, depth + 1, decision.badRefines);
        });
    }
};

}  // namespace

KdTree buildKdTree(std::span<const Bounds3f> primBounds, const KdTreeOptions& options) {
    kd::Root root = kd::rootOf(primBounds, options);
    if (!root.prims.empty()) Builder{primBounds, root.options, root.tree}.build(root.tree.bounds, root.prims, 0, 0);
    return std::move(root.tree);
}

}  // namespace rtlab
