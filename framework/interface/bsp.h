// The BSP tree of a5's optional extra (docs/bsp.md): space cut by planes in any direction,
// taken from the scene's own triangles (an autopartition). A KD-tree is the special case with
// axis-aligned planes.
//
//  * nodes[0] is the root; nodes are in depth-first order, back child first: an interior node's
//    back child is the node right after it, its front child is `front`.
//  * Every node lists primitives in primIndices[firstPrim .. firstPrim + primCount): an interior
//    node those lying in its plane, a leaf those in its cell.
#pragma once

#include "framework/core/bounds.h"

#include <cstdint>
#include <vector>

namespace rtlab {

// The deepest a BSP tree may be, and so the size of a traversal stack.
inline constexpr int kBspMaxDepthLimit = 64;
// How many of a node's triangles, spread evenly over its list, are tried as its plane, and what
// a cut primitive weighs against one primitive of imbalance between the sides.
inline constexpr int kBspCandidates = 8;
inline constexpr size_t kBspCutWeight = 4;
// Half the width of the band around a plane whose points count as lying in it, relative to the
// scene's largest coordinate (at least 1): far wider than the rounding of a dot product, so no
// primitive or ray is put on the wrong side by it.
inline constexpr double kBspRelativeThickness = 1e-6;

struct BspOptions {
    uint32_t maxPrims = 2;  // a cell with at most this many primitives is a leaf (1 .. 65535)
    int maxDepth = 40;      // 1 .. kBspMaxDepthLimit
};

struct BspNode {
    DVec3 normal{0.0};        // interior: the plane's unit normal; front is dot(normal, x) > offset
    double offset = 0.0;      // interior
    uint32_t front = 0;       // interior: the front child's index
    uint32_t firstPrim = 0;   // into BspTree::primIndices
    uint32_t primCount = 0;
    bool leaf = false;
};

struct BspTree {
    Bounds3f bounds;          // the union of the placeable primitives' boxes
    double thickness = 0.0;   // the band's half width: kBspRelativeThickness times the scale
    std::vector<BspNode> nodes;
    std::vector<uint32_t> primIndices;
};

}  // namespace rtlab
