// docs/a1-bvh.md, "Building", transcribed literally (the recursive way the page suggests):
// graded by tests/test_common_mistakes.cpp, it must keep full marks for a1, so the recipe is
// known to work as written. Deliberately not the reference's code (which uses an explicit stack).
#include "framework/interface/a1_bvh.h"

#include <limits>

namespace rtlab {
namespace {

// Builds the node for prims[begin, end) at the end of `nodes` and returns its index.
uint32_t build(std::vector<BuildPrimitive>& prims, uint32_t begin, uint32_t end, int depth, const BvhOptions& options,
               std::vector<BvhNode>& nodes) {
    std::span<BuildPrimitive> range(prims.data() + begin, end - begin);
    // 1. info = describeNode(range)
    NodeInfo info = describeNode(range);
    // 2. k = splitNode(range, info, depth, options); "primCount is 16 bits ... If splitNode
    //    returns 0 for a bigger range ..., split it with splitEqualCounts instead".
    uint32_t k = splitNode(range, info, depth, options);
    if (k == 0 && range.size() > std::numeric_limits<uint16_t>::max()) k = splitEqualCounts(range, info);
    // "Take node indices, never references into the vector: push_back may move it."
    auto index = static_cast<uint32_t>(nodes.size());
    nodes.push_back(BvhNode{});
    nodes[index].bounds = info.bounds;
    if (k == 0) {
        nodes[index].offset = begin;
        nodes[index].primCount = static_cast<uint16_t>(range.size());
        return index;
    }
    // "store the node, build its first child (which lands at i + 1), then write the index the
    // second child gets into offset"
    uint32_t first = build(prims, begin, begin + k, depth + 1, options, nodes);
    uint32_t second = build(prims, begin + k, end, depth + 1, options, nodes);
    nodes[index].offset = second;
    nodes[index].primCount = 0;
    // 3. axis = maxComponentIndex(second.bounds.centre() - first.bounds.centre())
    nodes[index].axis = static_cast<uint8_t>(maxComponentIndex(nodes[second].bounds.centre() - nodes[first].bounds.centre()));
    return index;
}

}  // namespace

Bvh buildBvh(std::vector<BuildPrimitive> prims, const BvhOptions& options) {
    Bvh bvh;
    if (prims.empty()) return bvh;
    bvh.nodes.reserve(2 * prims.size() - 1);  // "always enough"
    build(prims, 0, static_cast<uint32_t>(prims.size()), 0, options, bvh.nodes);
    // "at the end primIndices[i] = prims[i].index"
    bvh.primIndices.resize(prims.size());
    for (size_t i = 0; i < prims.size(); ++i) bvh.primIndices[i] = prims[i].index;
    return bvh;
}

}  // namespace rtlab
