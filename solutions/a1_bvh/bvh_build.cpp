// Reference solution: top-down BVH build into pbrt's depth-first node layout
// (docs/a1-bvh.md#building).
#include "framework/core/error.h"
#include "framework/interface/a1_bvh.h"

#include <limits>
#include <string>

namespace rtlab {
namespace {

// A node waiting to be built: its primitive range, what is known about it, and the parent
// whose `offset` must point at it if it is a second child.
struct BuildTask {
    uint32_t begin, end;
    int depth;
    uint32_t parentOfSecond;  // kNoParent unless this task is a second child
    NodeInfo info;
};
constexpr uint32_t kNoParent = std::numeric_limits<uint32_t>::max();
constexpr uint32_t kMaxLeafPrims = std::numeric_limits<uint16_t>::max();

}  // namespace

Bvh buildBvh(std::vector<BuildPrimitive> prims, const BvhOptions& options) {
    const auto n = static_cast<uint32_t>(prims.size());
    Bvh bvh;
    if (n == 0) return bvh;
    bvh.nodes.reserve(2 * size_t(n) - 1);  // a binary tree with n non-empty leaves has at most this

    // Depth-first with an explicit stack: the first child is pushed last, so it is popped (and
    // stored) right after its parent; the second child is stored once the first subtree is done.
    std::vector<BuildTask> stack;
    stack.reserve(2 * kMaxBvhDepth);
    std::span<const BuildPrimitive> all(prims);
    stack.push_back({0, n, 0, kNoParent, describeNode(all)});
    while (!stack.empty()) {
        BuildTask task = stack.back();
        stack.pop_back();
        auto nodeIndex = static_cast<uint32_t>(bvh.nodes.size());
        if (task.parentOfSecond != kNoParent) bvh.nodes[task.parentOfSecond].offset = nodeIndex;
        BvhNode& node = bvh.nodes.emplace_back();
        node.bounds = task.info.bounds;

        std::span<BuildPrimitive> range(prims.data() + task.begin, task.end - task.begin);
        uint32_t left = splitNode(range, task.info, task.depth, options);
        if (left == 0 && range.size() > kMaxLeafPrims) {
            // primCount is 16 bits wide: a leaf this big is split by counts, whatever the
            // heuristic wanted, as long as the depth limit allows it.
            if (task.depth >= kMaxBvhDepth - 1)
                throw Error("BVH build: " + std::to_string(range.size()) +
                            " primitives left at the maximum depth " + std::to_string(kMaxBvhDepth) +
                            " (a leaf holds at most 65535)");
            left = splitEqualCounts(range, task.info);
        }
        if (left == 0) {
            node.offset = task.begin;
            node.primCount = static_cast<uint16_t>(range.size());
            continue;
        }

        uint32_t middle = task.begin + left;
        NodeInfo first = describeNode(range.first(left));
        NodeInfo second = describeNode(range.subspan(left));
        node.primCount = 0;
        node.axis = static_cast<uint8_t>(maxComponentIndex(second.bounds.centre() - first.bounds.centre()));
        stack.push_back({middle, task.end, task.depth + 1, nodeIndex, second});
        stack.push_back({task.begin, middle, task.depth + 1, kNoParent, first});
    }

    bvh.primIndices.resize(n);
    for (uint32_t i = 0; i < n; ++i) bvh.primIndices[i] = prims[i].index;
    return bvh;
}

}  // namespace rtlab
