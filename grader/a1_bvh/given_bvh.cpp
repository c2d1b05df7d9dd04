#include "grader/a1_bvh/given_bvh.h"
#include "grader/a1_bvh/wire/bvh_codec.h"

#include <algorithm>

namespace rtlab::grader {
namespace {

constexpr size_t kMaxLeafSize = 4;

struct BvhMaker {
    Bvh bvh;
    std::vector<uint32_t> leafNodes;  // the node of each leaf, in the order of leaves.prims
    LeafList leaves;

    // The subtree over prims, depth first: the node, its first child right after it, then the
    // second, whose index the node keeps.
    void build(std::span<BuildPrimitive> prims) {
        auto index = uint32_t(bvh.nodes.size());
        bvh.nodes.emplace_back();
        Bounds3f bounds, centroids;
        for (const BuildPrimitive& p : prims) {
            bounds.extend(p.bounds);
            centroids.extend(p.centroid);
        }
        bvh.nodes[index].bounds = bounds;
        if (prims.size() <= kMaxLeafSize) {
            leafNodes.push_back(index);
            leaves.boxes.push_back(bounds);
            std::vector<uint32_t> ids;
            for (const BuildPrimitive& p : prims) ids.push_back(p.index);
            leaves.prims.push_back(std::move(ids));
            return;
        }
        int axis = centroids.longestAxis();
        auto middle = prims.begin() + std::ptrdiff_t(prims.size() / 2);
        std::nth_element(prims.begin(), middle, prims.end(), CentroidOrder{axis});
        build(prims.first(prims.size() / 2));
        bvh.nodes[index].offset = uint32_t(bvh.nodes.size());
        bvh.nodes[index].axis = uint8_t(axis);
        build(prims.subspan(prims.size() / 2));
    }
};

}  // namespace

GivenStructure givenBvh(const Scene& scene, uint64_t key) {
    std::vector<BuildPrimitive> prims;
    for (uint32_t i = 0; i < scene.primitiveCount(); ++i) {
        Bounds3f b = scene.primitiveBounds(i);
        if (isPlaceable(b)) prims.push_back(BuildPrimitive{b, b.centre(), i});
    }
    BvhMaker maker;
    if (!prims.empty()) maker.build(prims);

    GivenStructure given;
    leaveOut(maker.leaves, scene.primitiveCount(), key, true);
    for (size_t leaf = 0; leaf < maker.leafNodes.size(); ++leaf) {
        const auto& list = maker.leaves.prims[leaf];
        BvhNode& node = maker.bvh.nodes[maker.leafNodes[leaf]];
        node.offset = uint32_t(maker.bvh.primIndices.size());
        node.primCount = uint16_t(list.size());
        maker.bvh.primIndices.insert(maker.bvh.primIndices.end(), list.begin(), list.end());
    }
    ByteWriter out;
    writeBvh(out, maker.bvh);
    given.encoded = std::move(out.bytes());
    given.leaves = std::move(maker.leaves);
    return given;
}

}  // namespace rtlab::grader
