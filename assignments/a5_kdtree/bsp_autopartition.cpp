// Assignment a5, beyond the lecture: a BSP tree from the triangles' own planes (optional, graded
// by hit sets only).                               Guide: docs/bsp.md#rtlabs-autopartition
//
// Contract (framework/interface/a5_kdtree.h, framework/interface/bsp.h):
//   * buildBspAutopartition: the placeable primitives, tree.bounds their union, tree.thickness =
//     kBspRelativeThickness * max(1, the largest |coordinate| of tree.bounds). A node: a leaf if it
//     has at most options.maxPrims primitives or sits at options.maxDepth; otherwise, of the
//     triangles at indices k n / min(kBspCandidates, n) of its list, the plane (unit normal in
//     double, offset = dot(normal, first vertex)) with the lowest kBspCutWeight * cuts +
//     |front - back|; a leaf if there is none or it cuts more than half of the primitives. A primitive whose vertices (a sphere: its box's corners) all lie within
//     thickness of the plane stays in the node; the others go front, back or both. Nodes depth
//     first, back child first.
//   * intersectBsp / occludedBsp: the KD-tree's walk; at a node test its own primitives, then
//     with a = dot(n, o) - offset and b = dot(n, d) the ray is in front where a + b t >=
//     -thickness and behind where a + b t <= thickness: visit the near side's part of [tMin,
//     tMax] first, push the far side's part.
//   Try it with `rtlab render --accel bsp`.
//
// Hints:
//   * Without the band a vertex on the plane lands on either side by a rounding of the dot
//     product; with it, a ray is never sent past a primitive it could hit.
#include "framework/core/error.h"
#include "framework/interface/a5_kdtree.h"

namespace rtlab {

BspTree buildBspAutopartition(std::span<const std::array<Vec3, 3>> triangles, std::span<const Bounds3f> primBounds,
                              const BspOptions& options) {
    (void)triangles, (void)primBounds, (void)options;
    throw NotImplemented("a5 buildBspAutopartition (assignments/a5_kdtree/bsp_autopartition.cpp)");
}

bool intersectBsp(const BspTree& tree, Traversal& traversal, Hit& hit) {
    (void)tree, (void)traversal, (void)hit;
    throw NotImplemented("a5 intersectBsp (assignments/a5_kdtree/bsp_autopartition.cpp)");
}

bool occludedBsp(const BspTree& tree, Traversal& traversal) {
    (void)tree, (void)traversal;
    throw NotImplemented("a5 occludedBsp (assignments/a5_kdtree/bsp_autopartition.cpp)");
}

}  // namespace rtlab
