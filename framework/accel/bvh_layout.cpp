#include "framework/accel/bvh_layout.h"

#include <vector>

namespace rtlab {

std::string bvhLayoutProblem(const Bvh& bvh, size_t primitiveCount) {
    const size_t n = bvh.nodes.size();
    if (n == 0) return "";
    std::vector<uint8_t> reached(n, 0);
    std::vector<uint32_t> pending{0};
    while (!pending.empty()) {
        const uint32_t index = pending.back();
        pending.pop_back();
        // Made only for the message: a sound tree builds no strings.
        auto name = [index] { return "node " + std::to_string(index); };
        if (reached[index]++) return name() + " is reached twice from the root";
        const BvhNode& node = bvh.nodes[index];
        if (node.isLeaf()) {
            if (uint64_t(node.offset) + node.primCount > bvh.primIndices.size())
                return name() + ": its leaf range [" + std::to_string(node.offset) + ", " + std::to_string(uint64_t(node.offset) + node.primCount) +
                       ") runs past primIndices (" + std::to_string(bvh.primIndices.size()) + " entries)";
            for (uint32_t k = node.offset; k < node.offset + node.primCount; ++k)
                if (bvh.primIndices[k] >= primitiveCount)
                    return name() + ": primIndices[" + std::to_string(k) + "] = " + std::to_string(bvh.primIndices[k]) + " is not a primitive (there are " +
                           std::to_string(primitiveCount) + ")";
            continue;
        }
        // Children after their parent: a walk then only ever moves forward, and cannot cycle.
        if (uint64_t(index) + 1 >= n) return name() + " is interior, but its first child would be node " + std::to_string(index + 1) + ", past the last node";
        if (node.offset <= index + 1 || node.offset >= n)
            return name() + "'s second child is node " + std::to_string(node.offset) + ", which is not after its first child (node " + std::to_string(index + 1) +
                   ") and inside the " + std::to_string(n) + " nodes";
        pending.push_back(node.offset);
        pending.push_back(index + 1);
    }
    return "";
}

}  // namespace rtlab
