// Assignment a4, part 2: the octree's boxes and its build.   Guide: docs/a4-octree.md#building
//
// Contract (framework/interface/a4_octree.h, framework/interface/octree.h):
//   * octreeRootBox(bounds): bounds.isEmpty() -> Bounds3f(Vec3(0)). Else c = bounds.centre(),
//     s = the largest component of bounds.diagonal(), the cube [c - 0.5f * s, c + 0.5f * s]
//     extended to contain bounds.
//   * childBox(box, k): mid = box.centre(); per axis, bit set (4 = x, 2 = y, 1 = z):
//     [mid, upper], else [lower, mid].
//   * childIndex(p, mid): (p.x >= mid.x ? 4 : 0) | (p.y >= mid.y ? 2 : 0) | (p.z >= mid.z ? 1 : 0).
//   * buildOctree(input, options):
//       root = octreeRootBox(union of the boxes with isPlaceable); it holds every placeable
//       primitive in increasing id order. For a node with n primitives at depth d:
//         leaf  if n <= options.maxPrims or d == options.maxDepth;
//         else  child k gets, in order, the primitives that overlap
//               insertionBox(childBox(box, k)): a triangle (id < input.triangles.size())
//               by triangleOverlapsBox when options.insertion == Exact, everything else by
//               its bounding box (lower <= other.upper and upper >= other.lower on each axis);
//         leaf  also when two or more children would get all n (the memory rule).
//       A split node appends its 8 children to nodes at once (child k at firstChild + k),
//       then builds child 0 completely, then child 1, ... A leaf sets primStart =
//       primIndices.size() and appends its primitives. primCount = n for every node.
//
// Hints:
//   * Recursion: build(nodeIndex, box, prims, depth). Take the node's index, not a reference
//     into nodes: appending the children may move the array.
//   * A triangle's box overlapping the child is necessary for the triangle to overlap it, and
//     much cheaper: triangleOverlapsBox tests it first anyway (the three box normals).
//   * The primitives of a node are only needed until its children have them: pass each child
//     its own list and let the parent's go.
#include "framework/core/error.h"
#include "framework/interface/a4_octree.h"

namespace rtlab {

Bounds3f octreeRootBox(const Bounds3f& bounds) {
    (void)bounds;
    throw NotImplemented("a4 octreeRootBox (assignments/a4_octree/octree_build.cpp)");
}

Bounds3f childBox(const Bounds3f& box, int child) {
    (void)box, (void)child;
    throw NotImplemented("a4 childBox (assignments/a4_octree/octree_build.cpp)");
}

int childIndex(const Vec3& p, const Vec3& mid) {
    (void)p, (void)mid;
    throw NotImplemented("a4 childIndex (assignments/a4_octree/octree_build.cpp)");
}

Octree buildOctree(const OctreeInput& input, const OctreeOptions& options) {
    (void)input, (void)options;
    throw NotImplemented("a4 buildOctree (assignments/a4_octree/octree_build.cpp)");
}

}  // namespace rtlab
