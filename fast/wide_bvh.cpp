#include "fast/wide_bvh.h"

#include <algorithm>

namespace rtlab {
namespace {

template <int W>
class Collapser {
public:
    Collapser(const Bvh& binary, WideBvh<W>& wide) : binary_(binary), wide_(wide) {}

    // Emits the wide node whose children are the binary node's descendants chosen below, then
    // their subtrees (depth-first, so a subtree's nodes are stored together). A binary leaf
    // at the root becomes a wide node with one leaf child.
    uint32_t emit(uint32_t binaryIndex) {
        std::array<uint32_t, W> children{};
        int count = gatherChildren(binaryIndex, children);

        auto index = static_cast<uint32_t>(wide_.nodes.size());
        wide_.nodes.emplace_back();
        for (int slot = 0; slot < W; ++slot) wide_.nodes[index].setEmpty(slot);
        for (int slot = 0; slot < count; ++slot) {
            const BvhNode& child = binary_.nodes[children[slot]];
            uint32_t ref = child.isLeaf() ? (kLeafFlag | child.offset) : emit(children[slot]);
            // emit() may have grown the vector: index the node anew, never keep a reference.
            wide_.nodes[index].setChild(slot, child.bounds, ref, child.primCount);
        }
        return index;
    }

private:
    // The binary node's two children, with interior ones replaced by their own children,
    // largest surface area first, while there is room.
    int gatherChildren(uint32_t binaryIndex, std::array<uint32_t, W>& children) const {
        const BvhNode& node = binary_.nodes[binaryIndex];
        if (node.isLeaf()) {
            children[0] = binaryIndex;
            return 1;
        }
        children[0] = binaryIndex + 1;
        children[1] = node.offset;
        int count = 2;
        while (count < W) {
            int open = -1;
            float largestArea = -1.0f;
            for (int i = 0; i < count; ++i) {
                const BvhNode& candidate = binary_.nodes[children[i]];
                float area = candidate.bounds.surfaceArea();
                if (!candidate.isLeaf() && area > largestArea) {
                    open = i;
                    largestArea = area;
                }
            }
            if (open < 0) break;  // only leaves left
            uint32_t opened = children[open];
            children[open] = opened + 1;
            children[count++] = binary_.nodes[opened].offset;
        }
        return count;
    }

    const Bvh& binary_;
    WideBvh<W>& wide_;
};

}  // namespace

template <int W>
WideBvh<W> collapseToWide(const Bvh& binary) {
    WideBvh<W> wide;
    if (binary.nodes.empty()) return wide;
    wide.nodes.reserve(binary.nodes.size() / 2 + 1);  // about a third are needed; never regrows
    wide.primIndices.assign(binary.primIndices.begin(), binary.primIndices.end());
    Collapser<W>(binary, wide).emit(0);
    return wide;
}

template WideBvh<4> collapseToWide<4>(const Bvh&);
template WideBvh<8> collapseToWide<8>(const Bvh&);

}  // namespace rtlab
