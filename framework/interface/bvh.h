// The BVH data structure shared by assignments a1 and a2 (docs/a1-bvh.md): a flat array of
// 32-byte nodes in depth-first order, as pbrt lays them out.
//
//  * An interior node's first child is the node right after it; `offset` is its second child.
//  * A leaf (primCount > 0) covers primIndices[offset .. offset + primCount).
#pragma once

#include "framework/core/bounds.h"

#include <cstdint>
#include <span>
#include <vector>

namespace rtlab {

struct BvhNode {
    Bounds3f bounds;     // 24 bytes
    uint32_t offset;     // leaf: first entry in Bvh::primIndices; interior: second child
    uint16_t primCount;  // 0 for an interior node
    uint8_t axis;        // interior: the axis along which the second child lies beyond the
                         // first (0 = x, 1 = y, 2 = z); traversal visits the first child first
                         // when the ray's direction on this axis is positive
    uint8_t padding;

    bool isLeaf() const { return primCount > 0; }
};
static_assert(sizeof(BvhNode) == 32, "a BVH node is meant to fill half a cache line");

struct Bvh {
    std::vector<BvhNode> nodes;          // nodes[0] is the root
    std::vector<uint32_t> primIndices;   // primitive ids in leaf order
};

// What the builder knows about one primitive.
struct BuildPrimitive {
    Bounds3f bounds;
    Vec3 centroid;   // centre of bounds
    uint32_t index;  // primitive id
};

// The pinned order of primitives along an axis (docs/a1-bvh.md#ordering): by centroid
// coordinate, ties by primitive id, so every correct builder forms the same children. For
// example std::nth_element(first, middle, last, CentroidOrder{axis}). A NaN coordinate sorts
// like +inf, so even bad input keeps the order strict.
struct CentroidOrder {
    int axis;

    bool operator()(const BuildPrimitive& a, const BuildPrimitive& b) const {
        float ca = coordinate(a), cb = coordinate(b);
        return ca < cb || (ca == cb && a.index < b.index);
    }
    float coordinate(const BuildPrimitive& p) const {
        float c = p.centroid[axis];
        return c == c ? c : kInfinity;
    }
};

enum class SplitMethod { Median, Middle, EqualCounts, SahSweep, SahBuckets };

struct BvhOptions {
    SplitMethod method = SplitMethod::SahBuckets;
    int maxLeaf = 4;        // largest leaf a heuristic may keep (1 .. 65535)
    int buckets = 12;       // B for bucketed SAH (2 .. 32)
    bool allAxes = false;   // SAH: try all three axes instead of the longest centroid axis
};

// The node a split function is asked to divide.
struct NodeInfo {
    Bounds3f bounds;           // union of the primitives' bounds
    Bounds3f centroidBounds;   // bounds of their centroids
};

}  // namespace rtlab
