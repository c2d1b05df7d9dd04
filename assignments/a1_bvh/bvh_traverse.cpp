// Assignment a1, part 3: traversing the BVH.      Guide: docs/a1-bvh.md#traversal
//
// Contract (framework/interface/a1_bvh.h):
//   Test every box with traversal.hitsBox(box, tMax, &tEnter) and every primitive with
//   traversal.intersect(prim, hit) or traversal.occludes(prim): the framework counts them.
//   * intersectBvhRecursive: the lecture's pseudocode. `hit` arrives with hit.t = ray.tMax
//     and traversal.intersect shrinks it; pass hit.t as the box test's tMax. Return hit.found().
//   * intersectBvh: the same result without recursion. Keep a fixed array of kMaxBvhDepth
//     pending nodes (it cannot overflow: the builder never goes deeper). At an interior node
//     visit the near child first: the first child (index + 1) unless
//     traversal.dirIsNegative()[node.axis], then the second (node.offset). Remember each
//     pending child's tEnter and skip it when tEnter > hit.t by the time you get to it.
//   * occludedBvh: true as soon as any primitive blocks (tMin, tMax]; no ordering needed.
//
// Hints:
//   * Don't stop at the first hit in intersectBvh: the far child may hold a closer one.
//   * A helper `void visit(const Bvh&, uint32_t node, Traversal&, Hit&)` makes the
//     recursive version four lines.
#include "framework/core/error.h"
#include "framework/interface/a1_bvh.h"

namespace rtlab {

bool intersectBvhRecursive(const Bvh& bvh, Traversal& traversal, Hit& hit) {
    (void)bvh, (void)traversal, (void)hit;
    throw NotImplemented("a1 intersectBvhRecursive (assignments/a1_bvh/bvh_traverse.cpp)");
}

bool intersectBvh(const Bvh& bvh, Traversal& traversal, Hit& hit) {
    (void)bvh, (void)traversal, (void)hit;
    throw NotImplemented("a1 intersectBvh (assignments/a1_bvh/bvh_traverse.cpp)");
}

bool occludedBvh(const Bvh& bvh, Traversal& traversal) {
    (void)bvh, (void)traversal;
    throw NotImplemented("a1 occludedBvh (assignments/a1_bvh/bvh_traverse.cpp)");
}

}  // namespace rtlab
