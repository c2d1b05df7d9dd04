// Reference solution: the KD-tree's front-to-back traversal with a fixed stack, as pbrt walks it
// (docs/a5-kdtree.md#traversal).
#include "framework/interface/a5_kdtree.h"

#include <array>
#include <cmath>

namespace rtlab {

KdChildOrder kdChildOrder(int axis, float split, const Ray& ray, const RayInverse& inverse, float tMin, float tMax) {
    float o = ray.origin[axis], d = ray.direction[axis];
    float tSplit = (split - o) * inverse.invDirection[axis];
    // An origin on the plane: the side the ray moves into is near, below for d <= 0 (pbrt's 2011
    // fix; `d >= 0` sends a ray starting on the plane only into the side it leaves).
    bool belowFirst = o < split || (o == split && d <= 0.0f);
    // The plane behind the origin or beyond the segment: only the near side is crossed. The
    // margin: a ray through the corner where this plane meets an ancestor's crosses both at one
    // t, computed twice with different roundings; it must reach every cell at the corner.
    // Written so that NaN (0 * inf: a ray in the plane) fails both tests and visits both sides.
    if (tSplit > tMax * kKdRoundingMargin || tSplit <= 0.0f) return {belowFirst, true, false, tSplit};
    if (tSplit * kKdRoundingMargin < tMin) return {belowFirst, false, true, tSplit};
    return {belowFirst, true, true, tSplit};
}

namespace {

struct Pending {
    uint32_t node;
    float tMin, tMax;
};

// The ray's segment inside the tree's box: the entry from the slab test, the exit where the ray
// crosses the nearest far face (enlarged by its rounding error, so no leaf at the exit is lost).
bool segmentInTree(const KdTree& tree, Traversal& traversal, float tMax, float* tEnter, float* tExit) {
    if (tree.nodes.empty() || !traversal.hitsBox(tree.bounds, tMax, tEnter)) return false;
    const RayInverse& inverse = traversal.inverse();
    *tExit = tMax;
    for (int axis = 0; axis < 3; ++axis) {
        float face = tree.bounds[1 - inverse.dirIsNegative[axis]][axis];
        float t = (face - inverse.origin[axis]) * inverse.invDirection[axis] * kKdRoundingMargin;
        if (t < *tExit) *tExit = t;  // NaN (origin on a face, direction 0 along it) is skipped
    }
    return true;
}

// Walks the leaves the segment [tMin, tMax] crosses, near to far, and calls leaf(node) on each
// until it returns true. With closestHit, it also stops once every pending node lies beyond it.
template <typename Leaf>
void walk(const KdTree& tree, Traversal& traversal, float tMin, float tMax, const float* closestHit, Leaf&& leaf) {
    // A ray keeps at most one pending far child per level, and no tree is deeper than
    // kKdMaxDepthLimit.
    std::array<Pending, kKdMaxDepthLimit> stack;
    int pending = 0;
    uint32_t index = 0;
    for (;;) {
        const KdNode& node = tree.nodes[index];
        if (!node.isLeaf()) {
            traversal.countPlaneStep();
            KdChildOrder order = kdChildOrder(node.axis(), node.split(), traversal.ray(), traversal.inverse(), tMin, tMax);
            uint32_t below = index + 1, above = node.aboveChild();
            uint32_t first = order.belowFirst ? below : above, second = order.belowFirst ? above : below;
            if (!order.visitSecond) {
                index = first;
            } else if (!order.visitFirst) {
                index = second;
            } else {
                // A ray running in the plane (tSplit NaN) lies in both children all along.
                bool inPlane = std::isnan(order.tSplit);
                stack[pending++] = {second, inPlane ? tMin : order.tSplit, tMax};
                if (!inPlane) tMax = order.tSplit;
                index = first;
            }
            continue;
        }
        if (leaf(node) || pending == 0) return;
        Pending next = stack[--pending];
        // A hit nearer than where the next pending node begins cannot be beaten behind it. A
        // leaf's hit may lie beyond that leaf (its primitive reaches into later leaves); it stays
        // the candidate until then, and the mailbox keeps its primitive from being tested again.
        if (closestHit && *closestHit < next.tMin) return;
        index = next.node;
        tMin = next.tMin;
        tMax = next.tMax;
    }
}

std::span<const uint32_t> primitivesOf(const KdTree& tree, const KdNode& leaf) {
    return {tree.primIndices.data() + leaf.firstPrim(), leaf.primCount()};
}

}  // namespace

bool intersectKdTree(const KdTree& tree, Traversal& traversal, Hit& hit) {
    float tMin, tMax;
    if (!segmentInTree(tree, traversal, hit.t, &tMin, &tMax)) return false;
    walk(tree, traversal, tMin, tMax, &hit.t, [&](const KdNode& leaf) {
        for (uint32_t prim : primitivesOf(tree, leaf)) traversal.intersectOnce(prim, hit);
        return false;
    });
    return hit.found();
}

bool occludedKdTree(const KdTree& tree, Traversal& traversal) {
    float tMin, tMax;
    if (!segmentInTree(tree, traversal, traversal.ray().tMax, &tMin, &tMax)) return false;
    bool occluded = false;
    walk(tree, traversal, tMin, tMax, nullptr, [&](const KdNode& leaf) {
        for (uint32_t prim : primitivesOf(tree, leaf))
            if (traversal.occludesOnce(prim)) return occluded = true;
        return false;
    });
    return occluded;
}

}  // namespace rtlab
