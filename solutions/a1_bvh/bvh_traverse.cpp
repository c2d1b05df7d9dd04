// Reference solution: BVH traversal, first as the lecture's recursion, then iterative and
// ordered (docs/a1-bvh.md#traversal).
#include "framework/interface/a1_bvh.h"

namespace rtlab {

// --- The lecture's pseudocode -----------------------------------------------------------------

static void intersectNode(const Bvh& bvh, uint32_t index, Traversal& traversal, Hit& hit) {
    const BvhNode& node = bvh.nodes[index];
    float tEnter;
    if (!traversal.hitsBox(node.bounds, hit.t, &tEnter)) return;  // ray misses node.bbox
    if (node.isLeaf()) {
        // Every primitive; traversal.intersect keeps the closest hit in `hit`.
        for (uint32_t i = node.offset; i < node.offset + node.primCount; ++i)
            traversal.intersect(bvh.primIndices[i], hit);
        return;
    }
    // hit1 = Intersect(child1); hit2 = Intersect(child2); the shared `hit` keeps the closer one,
    // and child2 is already culled against child1's hit.
    intersectNode(bvh, index + 1, traversal, hit);
    intersectNode(bvh, node.offset, traversal, hit);
}

bool intersectBvhRecursive(const Bvh& bvh, Traversal& traversal, Hit& hit) {
    intersectNode(bvh, 0, traversal, hit);
    return hit.found();
}

// --- Iterative, ordered -----------------------------------------------------------------------
// Both children's boxes are tested at their parent (so a leaf is entered knowing its box is hit),
// the near one is visited next and the far one pushed with its entry distance. Each interior
// node on the current path holds at most one stack entry, and the builder caps the depth at
// kMaxBvhDepth - 1, so the fixed stack cannot overflow.

namespace {

struct StackEntry {
    uint32_t node;
    float tEnter;
};

// What testing both children of an interior node found: how many the ray hits (0, 1 or 2),
// the one to visit next (the nearer, if both are hit) and, if both are, the far one to push.
struct ChildHits {
    int count;
    StackEntry next, far;
};

// "Nearer" is decided by the direction's sign on the node's axis, not by distance: the second
// child lies beyond the first along that axis.
inline ChildHits testChildren(const Bvh& bvh, uint32_t index, Traversal& traversal, float tMax,
                              const std::array<int, 3>& dirIsNegative) {
    const BvhNode& node = bvh.nodes[index];
    uint32_t first = index + 1, second = node.offset;
    uint32_t nearChild = dirIsNegative[node.axis] ? second : first;
    uint32_t farChild = dirIsNegative[node.axis] ? first : second;
    float tNear, tFar;
    bool hitsNear = traversal.hitsBox(bvh.nodes[nearChild].bounds, tMax, &tNear);
    bool hitsFar = traversal.hitsBox(bvh.nodes[farChild].bounds, tMax, &tFar);
    if (hitsNear) return {hitsFar ? 2 : 1, {nearChild, tNear}, {farChild, tFar}};
    return {hitsFar ? 1 : 0, {farChild, tFar}, {}};
}

}  // namespace

bool intersectBvh(const Bvh& bvh, Traversal& traversal, Hit& hit) {
    const BvhNode* nodes = bvh.nodes.data();
    const uint32_t* primIndices = bvh.primIndices.data();
    const std::array<int, 3> dirIsNegative = traversal.dirIsNegative();
    StackEntry stack[kMaxBvhDepth];
    int stackSize = 0;

    float tEnter;
    if (!traversal.hitsBox(nodes[0].bounds, hit.t, &tEnter)) return false;
    uint32_t current = 0;
    for (;;) {
        const BvhNode& node = nodes[current];
        if (!node.isLeaf()) {
            ChildHits children = testChildren(bvh, current, traversal, hit.t, dirIsNegative);
            if (children.count == 2) stack[stackSize++] = children.far;
            if (children.count > 0) {
                current = children.next.node;
                continue;
            }
        } else {
            for (uint32_t i = node.offset, end = node.offset + node.primCount; i < end; ++i)
                traversal.intersect(primIndices[i], hit);
        }
        // Next pending child, skipping those that start beyond the closest hit so far.
        do {
            if (stackSize == 0) return hit.found();
            --stackSize;
        } while (stack[stackSize].tEnter > hit.t);
        current = stack[stackSize].node;
    }
}

bool occludedBvh(const Bvh& bvh, Traversal& traversal) {
    const BvhNode* nodes = bvh.nodes.data();
    const uint32_t* primIndices = bvh.primIndices.data();
    const std::array<int, 3> dirIsNegative = traversal.dirIsNegative();
    const float tMax = traversal.ray().tMax;
    StackEntry stack[kMaxBvhDepth];
    int stackSize = 0;

    float tEnter;
    if (!traversal.hitsBox(nodes[0].bounds, tMax, &tEnter)) return false;
    uint32_t current = 0;
    for (;;) {
        const BvhNode& node = nodes[current];
        if (!node.isLeaf()) {
            ChildHits children = testChildren(bvh, current, traversal, tMax, dirIsNegative);
            if (children.count == 2) stack[stackSize++] = children.far;
            if (children.count > 0) {
                current = children.next.node;
                continue;
            }
        } else {
            for (uint32_t i = node.offset, end = node.offset + node.primCount; i < end; ++i)
                if (traversal.occludes(primIndices[i])) return true;  // any blocker will do
        }
        if (stackSize == 0) return false;
        current = stack[--stackSize].node;  // no closest hit to skip against
    }
}

}  // namespace rtlab
