// What both reference KD-tree builders share (docs/a5-kdtree.md#building): the root, and how
// nodes and leaves are written into the tree.
#pragma once

#include "framework/core/error.h"
#include "framework/interface/a5_kdtree.h"

#include <vector>

namespace rtlab::kd {

// The root of a build: the placeable primitives in increasing order, the tree's box around them,
// and the options with the depth limit resolved (what kdDecideNode expects).
struct Root {
    KdTree tree;
    std::vector<uint32_t> prims;
    KdTreeOptions options;
};

inline Root rootOf(std::span<const Bounds3f> primBounds, const KdTreeOptions& options) {
    Root root;
    for (uint32_t prim = 0; prim < primBounds.size(); ++prim)
        if (isPlaceable(primBounds[prim])) {
            root.prims.push_back(prim);
            root.tree.bounds.extend(primBounds[prim]);
        }
    root.tree.maxDepth = options.maxDepth > 0 ? options.maxDepth : kdMaxDepth(root.prims.size());
    root.options = options;
    root.options.maxDepth = root.tree.maxDepth;
    return root;
}

// A node's child indices and a leaf's count share 30 bits with the node's flags.
inline uint32_t checkedIndex(size_t index) {
    if (index > kKdMaxIndex) throw Error("the KD-tree outgrew its 30-bit node and reference indices");
    return uint32_t(index);
}

inline void appendLeaf(KdTree& tree, std::span<const uint32_t> prims) {
    tree.nodes.push_back(KdNode::leaf(checkedIndex(tree.primIndices.size()), checkedIndex(prims.size())));
    tree.primIndices.insert(tree.primIndices.end(), prims.begin(), prims.end());
}

// The leaf rule for a node; search() finds its best plane, and runs only when the node is not a
// leaf by size or depth anyway (rule 1 of kdDecideNode).
template <typename Search>
KdNodeDecision decide(const KdTreeOptions& options, size_t primCount, int depth, int badRefines, KdSplit* best, Search&& search) {
    if (primCount > options.maxPrims && depth < options.maxDepth) *best = search();
    return kdDecideNode(uint32_t(primCount), depth, *best, badRefines, options);
}

// The children's primitives by kdClassify, in the input order, so both lists stay increasing.
// sideOf, when given, records each primitive's side by id.
struct Children {
    std::vector<uint32_t> below, above;
};

inline Children classify(std::span<const uint32_t> prims, std::span<const Bounds3f> primBounds, const KdSplit& split,
                         std::vector<KdSide>* sideOf = nullptr) {
    Children children;
    for (uint32_t prim : prims) {
        KdSide side = kdClassify(primBounds[prim], split.axis, split.position, split.planarSide);
        if (sideOf) (*sideOf)[prim] = side;
        if (side != KdSide::Above) children.below.push_back(prim);
        if (side != KdSide::Below) children.above.push_back(prim);
    }
    return children;
}

// A node's box cut at the split: the below child's (upper set to the plane) or the above child's.
inline Bounds3f childBox(Bounds3f box, const KdSplit& split, KdSide side) {
    (side == KdSide::Below ? box.upper : box.lower)[split.axis] = split.position;
    return box;
}

// An interior node in depth-first order: its slot, then the below subtree (buildChild(Below)),
// then the node itself with the above child's index, then the above subtree.
template <typename BuildChild>
void appendInterior(KdTree& tree, const KdSplit& split, BuildChild&& buildChild) {
    size_t node = tree.nodes.size();
    tree.nodes.emplace_back();  // written once the above child's index is known
    buildChild(KdSide::Below);
    tree.nodes[node] = KdNode::interior(split.axis, split.position, checkedIndex(tree.nodes.size()));
    buildChild(KdSide::Above);
}

}  // namespace rtlab::kd
