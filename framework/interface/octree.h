// The octree of assignment a4 (docs/a4-octree.md): a cube around the scene, cut at its centre
// into eight equal children, each cut again while it holds too many primitives. Nodes are one
// array: an interior node's eight children are the consecutive nodes firstChild .. firstChild + 7,
// a leaf lists its primitives in primIndices[primStart .. primStart + primCount).
#pragma once

#include "framework/core/bounds.h"
#include "framework/core/ray.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

namespace rtlab {

// Child indices are 0..7, one bit per axis: 4 = upper half in x, 2 = in y, 1 = in z.
inline constexpr int kOctreeChildren = 8;
// What nextNode returns when the ray leaves the parent: no ninth child.
inline constexpr int kOctreeEnd = 8;

enum class OctreeInsertion : uint8_t {
    Exact,  // a triangle goes into a child its own surface overlaps (triangleOverlapsBox)
    Box,    // every primitive goes into each child its bounding box overlaps
};

struct OctreeOptions {
    uint32_t maxPrims = 8;  // a node with more primitives than this is split ... (1 .. 65535)
    int maxDepth = 10;      // ... unless it lies at this depth; the root is at depth 0 (0 .. 20)
    OctreeInsertion insertion = OctreeInsertion::Exact;
};

struct OctreeNode {
    uint32_t firstChild = 0;  // interior: index of child 0 in Octree::nodes; 0 for a leaf
    uint32_t primStart = 0;   // leaf: its first entry in Octree::primIndices; 0 for an interior node
    uint32_t primCount = 0;   // the primitives inserted into this node (interior nodes too)

    // Node 0 is the root, so no child is ever node 0.
    bool isLeaf() const { return firstChild == 0; }
};

struct Octree {
    Bounds3f root;                      // octreeRootBox of the primitives' bounds
    std::vector<OctreeNode> nodes;      // nodes[0] is the root
    std::vector<uint32_t> primIndices;  // the leaves' lists, one after the other
};

// The box a primitive is tested against when it is dealt to a node: the node's box grown on
// every side by 2^-20 of its scale (the largest of its coordinates' magnitudes and its extent).
// The rounding of a float triangle-box test, and of a walk's ray parameters, stays well under
// that: a triangle that touches the node, at a vertex it shares with its neighbours say, is never
// left out of it, and the walk stays watertight. (The grader accepts either answer within 10^-5
// of the root's scale, far above it.)
inline Bounds3f insertionBox(const Bounds3f& box) {
    float scale = 0.0f;
    for (int a = 0; a < 3; ++a)
        scale = std::max({scale, std::abs(box.lower[a]), std::abs(box.upper[a]), box.upper[a] - box.lower[a]});
    Vec3 grow(scale * 0x1p-20f);
    return Bounds3f(box.lower - grow, box.upper + grow);
}

// What the octree is built over, by primitive id: every primitive's bounding box, and the
// vertices of the triangles, which come first (primitive i < triangles.size() is triangle i;
// the others, spheres, are inserted by their boxes).
struct OctreeInput {
    std::span<const Bounds3f> bounds;
    std::span<const std::array<Vec3, 3>> triangles;
};

// The ray of a traversal after mirroring (mirrorRay): every direction component made
// non-negative, and the axes that were flipped as child-index bits.
struct MirroredRay {
    Ray ray;
    int mask = 0;  // 4 if x was flipped, | 2 for y, | 1 for z
};

// Where a ray crosses a node's slabs, per axis, in the mirrored frame: it enters the x slab at
// t0.x and leaves it at t1.x, and so on. The node itself spans max(t0) .. min(t1).
struct NodeSpan {
    Vec3 t0;
    Vec3 t1;
};

}  // namespace rtlab
