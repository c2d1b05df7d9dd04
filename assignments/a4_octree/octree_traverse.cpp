// Assignment a4, part 4: traversing the octree.   Guide: docs/a4-octree.md#traversal
//
// Contract (framework/interface/a4_octree.h):
//   m = mirrorRay(octree.root, traversal.ray()), span = rootSpan(octree.root, m.ray). Walk the
//   root (node 0, box octree.root) only if max(t0) <= min(t1), min(t1) >= ray.tMin and
//   max(t0) <= hit.t (ray.tMax for occludedOctree), none of them NaN. At a node:
//     * min(span.t1) < ray.tMin: skip it;
//     * a leaf: traversal.enterLeaf(node), then its primitives through
//       traversal.intersectOnce(prim, hit) (occludedOctree: traversal.occludesOnce(prim),
//       true at the first blocker); the walk is over when hit.t <= min(span.t1);
//     * else tm = midParameters(m.ray, span, box), k = firstNode(span.t0, tm), and while
//       k != kOctreeEnd: child span = (tm, t1) on the axes whose bit k has, (t0, tm) on the
//       others; walk node nodes[firstChild + (k ^ m.mask)] with childBox(box, k); then
//       k = nextNode(k, child span's t1).
//   intersectOctree returns hit.found().
//
// Hints:
//   * The boxes you pass down are in the mirrored frame (the root is its own mirror image);
//     only the node index is flipped back, with k ^ mask.
//   * A hit beyond the leaf's exit is not final: a primitive reaching into later leaves may
//     be hit there, behind a nearer one in the next leaf. It stays in hit, and the mailbox keeps
//     its primitive from being tested again.
//   * Let the recursive walk return whether the whole traversal is over, and stop the loops
//     above it when it is.
#include "framework/core/error.h"
#include "framework/interface/a4_octree.h"

namespace rtlab {

bool intersectOctree(const Octree& octree, Traversal& traversal, Hit& hit) {
    (void)octree, (void)traversal, (void)hit;
    throw NotImplemented("a4 intersectOctree (assignments/a4_octree/octree_traverse.cpp)");
}

bool occludedOctree(const Octree& octree, Traversal& traversal) {
    (void)octree, (void)traversal;
    throw NotImplemented("a4 occludedOctree (assignments/a4_octree/octree_traverse.cpp)");
}

}  // namespace rtlab
