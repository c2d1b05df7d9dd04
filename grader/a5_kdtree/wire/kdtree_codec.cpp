#include "grader/a5_kdtree/wire/kdtree_codec.h"

#include "grader/a5_kdtree/wire/kdtree_inputs.h"
#include "grader/wire/index_checks.h"

namespace rtlab::grader {

void writeKdTree(ByteWriter& out, const KdTree& tree) {
    out.put(worker::KdTreeFrame{tree.bounds, tree.maxDepth});
    out.putVector(tree.nodes);
    out.putVector(tree.primIndices);
}

KdTree readKdTree(ByteReader& in, uint32_t primCount) {
    KdTree tree;
    auto frame = in.get<worker::KdTreeFrame>();
    tree.bounds = frame.bounds;
    tree.maxDepth = frame.maxDepth;
    tree.nodes = in.getVector<KdNode>(kMaxStructureEntries);
    tree.primIndices = in.getVector<uint32_t>(kMaxStructureEntries);
    if (tree.maxDepth < 0 || tree.maxDepth > kKdMaxDepthLimit) throw WireError("bad KD-tree depth limit");
    // Below child next, above child later: every link points forward, and no node lies deeper
    // than the limit a traversal sizes its stack by.
    std::vector<int> depth(tree.nodes.size(), 0);
    for (size_t i = 0; i < tree.nodes.size(); ++i) {
        const KdNode& node = tree.nodes[i];
        if (depth[i] > tree.maxDepth) throw WireError("a KD-tree node below the depth limit");
        if (node.isLeaf()) {
            checkLeafRange(node.firstPrim(), node.primCount(), tree.primIndices.size());
            continue;
        }
        if (node.axis() > 2 || i + 1 >= tree.nodes.size() || node.aboveChild() <= i + 1 || node.aboveChild() >= tree.nodes.size())
            throw WireError("a child link out of order");
        depth[i + 1] = depth[node.aboveChild()] = depth[i] + 1;
    }
    checkPrimitiveIds(tree.primIndices, primCount);
    return tree;
}

}  // namespace rtlab::grader
