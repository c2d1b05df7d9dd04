#include "grader/a4_octree/given_octree.h"
#include "grader/a4_octree/octree_oracle.h"
#include "grader/a4_octree/wire/octree_codec.h"

namespace rtlab::grader {
namespace {

constexpr size_t kMaxPrims = 8;
constexpr int kMaxDepth = 8;

struct OctreeMaker {
    const std::vector<Bounds3f>& primBounds;
    Octree octree;
    std::vector<uint32_t> leafNodes;  // the node of each leaf, in the order of leaves.prims
    LeafList leaves;

    // Node `index` over `box` with `prims`; its children, when it splits, are appended as a block.
    void build(uint32_t index, const Bounds3f& box, std::vector<uint32_t> prims, int depth) {
        octree.nodes[index].primCount = uint32_t(prims.size());
        std::array<std::vector<uint32_t>, kOctreeChildren> children;
        bool separates = false;
        if (prims.size() > kMaxPrims && depth < kMaxDepth) {
            for (int k = 0; k < kOctreeChildren; ++k) {
                Bounds3f child = insertionBox(expectedChildBox(box, k));
                for (uint32_t p : prims)
                    if (boxesOverlap(primBounds[p], child)) children[k].push_back(p);
                separates |= children[k].size() < prims.size();
            }
        }
        if (!separates) {
            leafNodes.push_back(index);
            leaves.boxes.push_back(box);
            leaves.prims.push_back(std::move(prims));
            return;
        }
        auto first = uint32_t(octree.nodes.size());
        octree.nodes[index].firstChild = first;
        octree.nodes.resize(first + kOctreeChildren);
        for (int k = 0; k < kOctreeChildren; ++k) build(first + uint32_t(k), expectedChildBox(box, k), std::move(children[k]), depth + 1);
    }
};

}  // namespace

GivenStructure givenOctree(const Scene& scene, uint64_t key) {
    std::vector<Bounds3f> primBounds;
    Bounds3f all;
    std::vector<uint32_t> placeable;
    for (uint32_t i = 0; i < scene.primitiveCount(); ++i) {
        primBounds.push_back(scene.primitiveBounds(i));
        if (!isPlaceable(primBounds.back())) continue;
        all.extend(primBounds.back());
        placeable.push_back(i);
    }
    OctreeMaker maker{primBounds, {}, {}, {}};
    maker.octree.root = expectedRootBox(all);
    maker.octree.nodes.resize(1);
    maker.build(0, maker.octree.root, std::move(placeable), 0);

    GivenStructure given;
    leaveOut(maker.leaves, scene.primitiveCount(), key, false);
    for (size_t leaf = 0; leaf < maker.leafNodes.size(); ++leaf) {
        OctreeNode& node = maker.octree.nodes[maker.leafNodes[leaf]];
        node.primStart = uint32_t(maker.octree.primIndices.size());
        node.primCount = uint32_t(maker.leaves.prims[leaf].size());
        maker.octree.primIndices.insert(maker.octree.primIndices.end(), maker.leaves.prims[leaf].begin(), maker.leaves.prims[leaf].end());
    }
    ByteWriter out;
    writeOctree(out, maker.octree);
    given.encoded = std::move(out.bytes());
    given.leaves = std::move(maker.leaves);
    return given;
}

}  // namespace rtlab::grader
