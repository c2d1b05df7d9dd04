// Assignment a5 (docs/a5-kdtree.md): the KD-tree, built by the surface area heuristic and
// traversed front to back. Implemented in assignments/a5_kdtree/ (yours) and solutions/a5_kdtree/
// (reference). Every rule below is pinned, so every correct implementation builds the same tree.
#pragma once

#include "framework/core/hit.h"
#include "framework/interface/bsp.h"
#include "framework/interface/kdtree.h"
#include "framework/interface/traversal.h"

namespace rtlab {

// --- The cost of a plane (assignments/a5_kdtree/kd_sah.cpp) ------------------------------------

// The SAH cost of cutting node at position on axis with nBelow primitives below and nAbove above:
//   K_T + K_I (1 - eb) (SA_below / SA nBelow + SA_above / SA nAbove)
// SA, SA_below, SA_above: the surface areas of node and of its halves (node with upper[axis] =
// position, and with lower[axis] = position), in double from the float coordinates: extents as
// double differences, SA = 2 (dx dy + dy dz + dz dx). eb = costs.emptyBonus when nBelow or nAbove
// is 0, else 0. A node of area 0 (a point or a segment) costs +infinity: it is never split.
double kdSahCost(const Bounds3f& node, int axis, float position, uint32_t nBelow, uint32_t nAbove, const KdCosts& costs);

// --- Events (assignments/a5_kdtree/kd_events.cpp) ----------------------------------------------

// The order of events along an axis: by position, then by type (End < Planar < Start), then by
// primitive index. True when a comes strictly before b.
bool kdEventBefore(const KdEvent& a, const KdEvent& b);

// The events of the boxes of prims (ids into primBounds) on axis, sorted by kdEventBefore: a box
// with lower[axis] == upper[axis] gives one Planar event there, any other box a Start at
// lower[axis] and an End at upper[axis].
std::vector<KdEvent> kdSortedEvents(std::span<const uint32_t> prims, std::span<const Bounds3f> primBounds, int axis);

// --- Splitting a node (assignments/a5_kdtree/kd_split.cpp) -------------------------------------

// One node's events, sorted, one list per axis (x, y, z).
using KdNodeEvents = std::array<std::span<const KdEvent>, 3>;

// The cheapest plane for a node with primCount primitives, found in one sweep per axis, x then y
// then z. Candidates are the event positions p strictly inside the node (lower[axis] < p <
// upper[axis]). At a candidate, with
//   nLess   the primitives whose box starts before p (lower < p),
//   nPlanar those lying in the plane (their Planar event is at p),
//   nMore   those whose box ends after p (upper > p),
// two splits are scored with kdSahCost: planar below (nBelow = nLess + nPlanar, nAbove = nMore),
// then planar above (nLess, nMore + nPlanar). The first strictly cheapest wins: ties go to the
// lower axis, then the lower position, then planar below. No candidate: KdSplit{} (axis -1).
KdSplit kdBestSplit(const Bounds3f& node, const KdNodeEvents& events, uint32_t primCount, const KdCosts& costs);

// The side of the plane (axis, position) a primitive with box goes to, by its coordinates:
//   below if lower < position, or lower == upper == position and planarSide is Below;
//   above if upper > position, or lower == upper == position and planarSide is Above;
// Both when both hold. A box touching the plane from one side goes to that side only.
KdSide kdClassify(const Bounds3f& box, int axis, float position, KdSide planarSide);

// --- When to stop (assignments/a5_kdtree/kd_leaf.cpp) ------------------------------------------

// The depth limit for N primitives, pbrt's rule: lround(8 + 1.3 * floor(log2 N)) in double,
// floor(log2 N) exactly (the index of N's highest set bit); 8 for N <= 1; at most
// kKdMaxDepthLimit.
int kdMaxDepth(size_t primCount);

// The leaf rule, for a node of primCount primitives at depth (0 at the root) whose cheapest split
// is best (KdSplit{} when it has none or none was searched), with the bad refines its parent
// passed down, and options.maxDepth resolved (never 0). In this order:
//   1. primCount <= options.maxPrims or depth >= options.maxDepth: a leaf;
//   2. no split (!best.found()): a leaf;
//   3. with leafCost = K_I * primCount, best.cost > leafCost is one more bad refine;
//   4. a leaf if best.cost > 4 * leafCost and primCount < 16, or badRefines >= kKdMaxBadRefines;
//   5. otherwise a split.
// Returns the decision and the bad refines after step 3 (what the children inherit).
KdNodeDecision kdDecideNode(uint32_t primCount, int depth, const KdSplit& best, int badRefines, const KdTreeOptions& options);

// --- Building (assignments/a5_kdtree/kd_build.cpp) ---------------------------------------------

// The KD-tree over primBounds (indexed by primitive id), each node sorting its own events:
//  * the root holds the placeable primitives (isPlaceable) in increasing order, its box is the
//    union of theirs (tree.bounds), depth 0, no bad refines; tree.maxDepth is options.maxDepth
//    if > 0, else kdMaxDepth(their count). No placeable primitive: no nodes.
//  * a node: kdSortedEvents of its primitives on x, y and z, kdBestSplit, kdDecideNode (a node
//    that rule 1 makes a leaf needs no search). A split hands each primitive to the child or
//    children kdClassify names; the children's boxes are the node's with upper[axis] (below) or
//    lower[axis] (above) set to the position; their primitives stay in increasing order.
//  * nodes in depth-first order, below child first (KdNode::interior, KdNode::leaf); a leaf lists
//    its primitives in increasing order.
KdTree buildKdTree(std::span<const Bounds3f> primBounds, const KdTreeOptions& options);

// --- Traversal (assignments/a5_kdtree/kd_traverse.cpp) -----------------------------------------

// Where a ray goes at an interior node with the plane (axis, split), for its segment
// [tMin, tMax] inside the node; o and d are ray.origin[axis] and ray.direction[axis], and
// m = kKdRoundingMargin:
//   tSplit     = (split - o) * inverse.invDirection[axis], in float
//   belowFirst = o < split || (o == split && d <= 0)
//   tSplit > tMax * m or tSplit <= 0: the first (near) child only;
//   otherwise tSplit * m < tMin: the second (far) child only;
//   otherwise both (also for a NaN tSplit: a ray running in the plane).
// The margin keeps a ray through the corner where two planes meet in every cell at the corner.
KdChildOrder kdChildOrder(int axis, float split, const Ray& ray, const RayInverse& inverse, float tMin, float tMax);

// Closest hit, front to back, with a stack of kKdMaxDepthLimit pending nodes:
//  * no nodes: false. The segment in the tree: tMin from traversal.hitsBox(tree.bounds, hit.t,
//    &tMin) (a miss: false), tMax = min(hit.t, the ray's exit from tree.bounds: the smallest
//    far-face distance (face - o) * invDirection over the axes, NaN ones skipped, times
//    kKdRoundingMargin, as the slab test enlarges its far distance).
//  * an interior node: traversal.countPlaneStep(), kdChildOrder; when both children are visited,
//    push the far one with [tSplit, tMax] and go on with the near one over [tMin, tSplit] (a NaN
//    tSplit gives both the whole [tMin, tMax]).
//  * a leaf: traversal.intersectOnce(prim, hit) for each of its primitives, then pop the next
//    pending node; stop when none is left or when hit.t < its tMin (the rest lies beyond the hit).
// Returns hit.found().
bool intersectKdTree(const KdTree& tree, Traversal& traversal, Hit& hit);
// Any hit in (ray.tMin, ray.tMax]: the same walk over [tMin, min(ray.tMax, exit)], true at the
// first traversal.occludesOnce(prim) that blocks the ray.
bool occludedKdTree(const KdTree& tree, Traversal& traversal);

// --- Beyond the lecture (assignments/a5_kdtree/kd_build_nlogn.cpp; optional) -------------------

// The same tree as buildKdTree, bit for bit, in O(N log N) (Wald and Havran 2006): the events of
// the root's primitives are sorted once per axis; a split hands each axis's sorted list down,
// every event to the child or children its primitive goes to, in order, so no node sorts again.
KdTree buildKdTreeNlogN(std::span<const Bounds3f> primBounds, const KdTreeOptions& options);

// --- Beyond the lecture: a BSP autopartition (assignments/a5_kdtree/bsp_autopartition.cpp;
// optional, graded by hit sets only) ----------------------------------------------------------

// A BSP tree whose planes are the planes of the scene's own triangles (docs/bsp.md#rtlabs-autopartition).
// triangles[i] are the vertices of primitive i for i < triangles.size(); the others (spheres)
// are classified by the corners of their boxes. A node with more than options.maxPrims
// primitives and less deep than options.maxDepth tries the planes of kBspCandidates of its
// triangles spread evenly over its list (the k-th at index k n / min(8, n); degenerate ones
// skipped) and takes the lowest kBspCutWeight * cuts + |front - back| (ties: the earlier one);
// primitives within tree.thickness of the plane stay in the node, the others go to the front,
// the back or both children. A leaf when no candidate is left, or when the best plane cuts more
// than half of the node's primitives.
BspTree buildBspAutopartition(std::span<const std::array<Vec3, 3>> triangles, std::span<const Bounds3f> primBounds,
                              const BspOptions& options);
// Closest hit and any hit, front to back: at a node, its own primitives, then the near side
// over the part of the segment where the ray is within tree.thickness of that side, then the far
// side over its part.
bool intersectBsp(const BspTree& tree, Traversal& traversal, Hit& hit);
bool occludedBsp(const BspTree& tree, Traversal& traversal);

}  // namespace rtlab
