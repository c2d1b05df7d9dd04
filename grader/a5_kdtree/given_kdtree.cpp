#include "grader/a5_kdtree/given_kdtree.h"
#include "grader/a5_kdtree/wire/kdtree_codec.h"

namespace rtlab::grader {
namespace {

constexpr size_t kMaxPrims = 4;
constexpr int kMaxDepth = 16;

struct KdTreeMaker {
    const std::vector<Bounds3f>& primBounds;
    KdTree tree;
    std::vector<uint32_t> leafNodes;  // the node of each leaf, in the order of leaves.prims
    LeafList leaves;

    // The subtree of a node over `box`, appended in pbrt's layout: the node, its below subtree
    // right after it, then its above subtree.
    void build(const Bounds3f& box, std::vector<uint32_t> prims, int depth) {
        auto index = uint32_t(tree.nodes.size());
        tree.nodes.emplace_back();
        int axis = box.longestAxis();
        float lo = box.lower[axis], hi = box.upper[axis], split = 0.5f * (lo + hi);
        std::vector<uint32_t> below, above;
        if (prims.size() > kMaxPrims && depth < kMaxDepth && lo < split && split < hi) {
            for (uint32_t p : prims) {
                const Bounds3f& b = primBounds[p];
                bool planar = b.lower[axis] == split && b.upper[axis] == split;
                if (b.lower[axis] < split || planar) below.push_back(p);
                if (b.upper[axis] > split || planar) above.push_back(p);
            }
        }
        if (below.size() + above.size() == 0 || (below.size() == prims.size() && above.size() == prims.size())) {
            leafNodes.push_back(index);
            leaves.boxes.push_back(box);
            leaves.prims.push_back(std::move(prims));
            return;
        }
        Bounds3f belowBox = box, aboveBox = box;
        belowBox.upper[axis] = split;
        aboveBox.lower[axis] = split;
        build(belowBox, std::move(below), depth + 1);
        tree.nodes[index] = KdNode::interior(axis, split, uint32_t(tree.nodes.size()));
        build(aboveBox, std::move(above), depth + 1);
    }
};

}  // namespace

GivenStructure givenKdTree(const Scene& scene, uint64_t key) {
    std::vector<Bounds3f> primBounds;
    std::vector<uint32_t> placeable;
    KdTreeMaker maker{primBounds, {}, {}, {}};
    for (uint32_t i = 0; i < scene.primitiveCount(); ++i) {
        primBounds.push_back(scene.primitiveBounds(i));
        if (!isPlaceable(primBounds.back())) continue;
        maker.tree.bounds.extend(primBounds.back());
        placeable.push_back(i);
    }
    maker.tree.maxDepth = kMaxDepth;
    if (!placeable.empty()) maker.build(maker.tree.bounds, std::move(placeable), 0);

    GivenStructure given;
    leaveOut(maker.leaves, scene.primitiveCount(), key, false);
    for (size_t leaf = 0; leaf < maker.leafNodes.size(); ++leaf) {
        const auto& list = maker.leaves.prims[leaf];
        maker.tree.nodes[maker.leafNodes[leaf]] = KdNode::leaf(uint32_t(maker.tree.primIndices.size()), uint32_t(list.size()));
        maker.tree.primIndices.insert(maker.tree.primIndices.end(), list.begin(), list.end());
    }
    ByteWriter out;
    writeKdTree(out, maker.tree);
    given.encoded = std::move(out.bytes());
    given.leaves = std::move(maker.leaves);
    return given;
}

}  // namespace rtlab::grader
