// Assignment a5, part 6: traversing the tree.      Guide: docs/a5-kdtree.md#traversal
//
// Contract (framework/interface/a5_kdtree.h):
//   * kdChildOrder: tSplit = (split - o) * inverse.invDirection[axis] (o = ray.origin[axis]);
//     belowFirst = o < split || (o == split && d <= 0) (d = ray.direction[axis]); with
//     m = kKdRoundingMargin: tSplit > tMax * m || tSplit <= 0: {belowFirst, first only}; else
//     tSplit * m < tMin: second only; else both.
//   * intersectKdTree: no nodes -> false. tMin from traversal.hitsBox(tree.bounds, hit.t, &tMin)
//     (false on a miss); tMax = min(hit.t, exit), exit = the smallest over the axes of
//     (far face - o) * invDirection * kKdRoundingMargin, NaN skipped (far face:
//     tree.bounds[1 - dirIsNegative[axis]][axis]). Loop from the root with a stack of
//     kKdMaxDepthLimit entries {node, tMin, tMax}:
//       interior: traversal.countPlaneStep(); order = kdChildOrder(...); the below child is
//         index + 1, the above child node.aboveChild(). Both: push {second, tSplit, tMax}, go on
//         with first over [tMin, tSplit] (NaN tSplit: both keep [tMin, tMax]). One: go on with it.
//       leaf: traversal.intersectOnce(prim, hit) for each primitive; then pop; stop when the stack
//         is empty or hit.t < the popped tMin.
//     Return hit.found().
//   * occludedKdTree: the same walk with ray.tMax; true at the first traversal.occludesOnce(prim).
//
// Hints:
//   * `d >= 0` in belowFirst was pbrt's bug until 2011: a ray starting on the plane and moving
//     up would visit only the below child (tSplit = 0 <= 0 means "first only").
//   * A leaf's hit may lie beyond the leaf: keep it and go on; the pop test ends the walk.
//   * Without the margin m, a ray through a vertex where two planes meet can skip the one cell
//     whose triangles it hits: two roundings of the same crossing disagree.
#include "framework/core/error.h"
#include "framework/interface/a5_kdtree.h"

namespace rtlab {

KdChildOrder kdChildOrder(int axis, float split, const Ray& ray, const RayInverse& inverse, float tMin, float tMax) {
    (void)axis, (void)split, (void)ray, (void)inverse, (void)tMin, (void)tMax;
    throw NotImplemented("a5 kdChildOrder (assignments/a5_kdtree/kd_traverse.cpp)");
}

bool intersectKdTree(const KdTree& tree, Traversal& traversal, Hit& hit) {
    (void)tree, (void)traversal, (void)hit;
    throw NotImplemented("a5 intersectKdTree (assignments/a5_kdtree/kd_traverse.cpp)");
}

bool occludedKdTree(const KdTree& tree, Traversal& traversal) {
    (void)tree, (void)traversal;
    throw NotImplemented("a5 occludedKdTree (assignments/a5_kdtree/kd_traverse.cpp)");
}

}  // namespace rtlab
