// A W-wide BVH (W = 4 or 8) made from the binary BVH of assignments a1/a2 (docs/performance.md,
// "The wide BVH"). Production tracers (Embree, tinybvh's BVH4/BVH8) traverse trees like this
// one: a node holds the boxes of up to W children side by side, so one SIMD slab test decides
// all of them, and the tree has a half (W = 4) or a third (W = 8) of the levels to walk.
//
// The tree is the student's (or the reference) binary tree with levels of interior nodes folded
// into their parents: same leaves, same primitives, only fewer interior nodes.
#pragma once

#include "fast/huge_page_allocator.h"
#include "framework/interface/bvh.h"

#include <array>
#include <cstdint>
#include <vector>

namespace rtlab {

// A reference to a child: an interior node's index, or (kLeafFlag set) the first entry of a
// leaf in WideBvh::primIndices.
inline constexpr uint32_t kLeafFlag = 0x80000000u;

template <int W>
struct alignas(64) WideBvhNode {
    // The children's box planes, one row per plane and a column per child: rows 0-2 are the
    // lower x, y, z, rows 3-5 the upper x, y, z. A row is ready for one W-wide load. An unused
    // slot has an empty box (lower = +inf, upper = -inf), which no ray hits, and refers to a
    // leaf of no primitives.
    float planes[6][W];
    uint32_t child[W];
    uint32_t primCount[W];  // leaf children: how many primitives; interior: 0

    static constexpr int lowerRow(int axis) { return axis; }
    static constexpr int upperRow(int axis) { return 3 + axis; }

    void setChild(int slot, const Bounds3f& box, uint32_t ref, uint32_t count) {
        for (int axis = 0; axis < 3; ++axis) {
            planes[lowerRow(axis)][slot] = box.lower[axis];
            planes[upperRow(axis)][slot] = box.upper[axis];
        }
        child[slot] = ref;
        primCount[slot] = count;
    }
    void setEmpty(int slot) { setChild(slot, Bounds3f{}, kLeafFlag, 0); }
};
static_assert(sizeof(WideBvhNode<4>) == 128 && sizeof(WideBvhNode<8>) == 256,
              "a wide node is meant to fill two (W = 4) or four (W = 8) cache lines");

template <int W>
struct WideBvh {
    HugePageVector<WideBvhNode<W>> nodes;  // [0] is the root
    HugePageVector<uint32_t> primIndices;  // ids in leaf order
};

// Folds a binary BVH into a W-wide one. A node's children are found by repeatedly opening the
// interior child with the largest surface area (its rays are the likeliest to need it) until
// there are W or only leaves are left. An empty binary tree gives an empty wide one.
template <int W>
WideBvh<W> collapseToWide(const Bvh& binary);

}  // namespace rtlab
