// A four-wide BVH made from the binary BVH of assignments a1/a2 (docs/performance.md, "The
// wide BVH"). Production tracers (Embree, tinybvh's BVH4/BVH8) traverse trees like this one:
// a node holds the boxes of up to four children side by side, so one SIMD slab test decides
// all four, and the tree has about half as many levels to walk.
//
// The tree is the student's (or the reference) binary tree with every other level of interior
// nodes folded into its parent: same leaves, same primitives, only fewer interior nodes.
#pragma once

#include "framework/interface/bvh.h"

#include <array>
#include <cstdint>
#include <vector>

namespace rtlab {

inline constexpr int kWideBvhWidth = 4;

// A reference to a child: an interior node's index, or (kLeafFlag set) the first entry of a
// leaf in WideBvh::primIndices.
inline constexpr uint32_t kLeafFlag = 0x80000000u;

struct alignas(64) WideBvhNode {
    // The children's box planes, one row per plane and a column per child: rows 0-2 are the
    // lower x, y, z, rows 3-5 the upper x, y, z. A row is ready for one 4-wide load. An unused
    // slot has an empty box (lower = +inf, upper = -inf), which no ray hits, and refers to a
    // leaf of no primitives.
    float planes[6][kWideBvhWidth];
    uint32_t child[kWideBvhWidth];
    uint32_t primCount[kWideBvhWidth];  // leaf children: how many primitives; interior: 0

    static constexpr int lowerRow(int axis) { return axis; }
    static constexpr int upperRow(int axis) { return 3 + axis; }
};
static_assert(sizeof(WideBvhNode) == 128, "a wide node is meant to fill two cache lines");

struct WideBvh {
    std::vector<WideBvhNode> nodes;     // nodes[0] is the root, depth-first order
    std::vector<uint32_t> primIndices;  // primitive ids in leaf order (the binary tree's)
};

// Folds a binary BVH into a four-wide one. A node's children are found by repeatedly opening
// the interior child with the largest surface area (its rays are the likeliest to need it)
// until there are four or only leaves are left. An empty binary tree gives an empty wide one.
WideBvh collapseToWide(const Bvh& binary);

}  // namespace rtlab
