// fast/'s own builder of the W-wide BVH (--accel fastbvh; docs/performance.md, "The fast
// BVH's builder"). The wide BVHs bvh4 and bvh8 fold the student's binary tree, whose SAH prices
// a leaf by its triangles (C_isect = C_trav = 1): leaves of about two triangles, so half of each
// four-triangle packet is padding. This builder prices what the traversal pays instead:
//
//  * a leaf costs one intersection per packet it fills (ceil(n / 4)), so leaves fill packets;
//  * the SAH is binned (32 bins by default) on all three axes, as Embree's builders do;
//  * the wide node is built directly: its children are found by splitting, again and again, the
//    child with the largest surface area that the SAH says to split, until there are W;
//  * binning big nodes and building subtrees run on every thread the process may use.
//
// The tree has the layout of WideBvh, so the wide traversal (wide_bvh_accelerator.h) and its
// triangle packets are the same for both trees: what the builder gains is measured alone.
#pragma once

#include "fast/wide_bvh.h"
#include "framework/core/bounds.h"

#include <span>

namespace rtlab {

struct WideBvhBuildOptions {
    int maxLeaf = 8;            // a leaf never holds more triangles, unless the depth cap forces it
    int bins = 32;              // SAH bins per axis (2 .. kMaxSahBins)
    float traversalCost = 1.0f;  // C_trav: one wide node test
    // C_isect: one packet of four triangles, as Embree prices a block of four against a node.
    // With 2 (the packet test takes about twice an eight-wide slab test's instructions) rays run
    // 4-6 % fewer instructions but no faster, in a tree of 15 % more bytes (docs/performance.md,
    // "The fast BVH's builder").
    float packetCost = 1.0f;
    int threads = 0;             // 0: every CPU this process may run on
};

inline constexpr int kMaxSahBins = 32;

// Builds over the primitives' boxes (index = primitive id). Leaves refer to their first entry
// in primIndices, as collapseToWide's do. No primitives give an empty tree.
template <int W>
WideBvh<W> buildWideBvh(std::span<const Bounds3f> primBounds, const WideBvhBuildOptions& options);

}  // namespace rtlab
