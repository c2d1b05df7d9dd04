// Assignment a4 (docs/a4-octree.md): the octree, its exact triangle-box insertion and the
// parametric front-to-back traversal of Revelles, Urena and Lastra (2000).
// Implemented in assignments/a4_octree/ (yours) and solutions/a4_octree/ (reference).
#pragma once

#include "framework/core/hit.h"
#include "framework/interface/octree.h"
#include "framework/interface/traversal.h"

namespace rtlab {

// --- Triangle and box (assignments/a4_octree/triangle_box.cpp) ---------------------------------

// Does the closed triangle p0 p1 p2 share a point with the closed box? Akenine-Moller's
// separating-axis test (2001) over 13 axes: the three box normals, the triangle's normal and
// the nine cross products of a triangle edge with a box axis. Inclusive: a triangle that only
// touches the box (a vertex on a face, an edge along an edge) overlaps it; an axis separates
// only when the two projections are disjoint with a gap. Degenerate triangles (a segment, a
// point) are tested as what they are. NaN anywhere: no overlap.
bool triangleOverlapsBox(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Bounds3f& box);

// --- Building (assignments/a4_octree/octree_build.cpp) ------------------------------------------

// The root cube of primitives whose union of boxes is bounds: centred on bounds (centre =
// bounds.centre(), in float), side = the longest extent s, i.e. [centre - 0.5f * s,
// centre + 0.5f * s] on every axis, then extended to contain bounds (float rounding may leave
// the cube an ulp short of it). An empty box (no placeable primitive) gives the point box at
// the origin.
Bounds3f octreeRootBox(const Bounds3f& bounds);

// Child `child` (0..7) of box: with mid = box.centre() = 0.5f * (lower + upper), computed once,
// the child has [mid[a], upper[a]] on axis a when its bit for a is set (4 = x, 2 = y, 1 = z)
// and [lower[a], mid[a]] otherwise. Neighbouring children share the mid-plane exactly.
Bounds3f childBox(const Bounds3f& box, int child);

// The child of a node with centre mid that holds point p: bit 4 if p.x >= mid.x, | 2 if
// p.y >= mid.y, | 1 if p.z >= mid.z. A point on a mid-plane goes to the upper side (-0.0 >= +0.0
// too); a NaN coordinate to the lower side.
int childIndex(const Vec3& p, const Vec3& mid);

// The octree over input (see OctreeInput) by these rules:
//   * root = octreeRootBox(the union of the isPlaceable boxes); the root holds every placeable
//     primitive, in increasing id order; the others go nowhere.
//   * A node with n primitives at depth d (the root at 0) is a leaf when n <= options.maxPrims
//     or d == options.maxDepth. Otherwise its primitives are dealt to its eight children: child
//     k receives, in the parent's order, each primitive that overlaps insertionBox(childBox(box,
//     k)) (octree.h: the child's box grown by 2^-20 of its scale): a triangle when
//     triangleOverlapsBox (OctreeInsertion::Exact) or when its bounding box does (Box), a
//     sphere when its bounding box does. Boxes overlap when lower[a] <= other.upper[a] and
//     upper[a] >= other.lower[a] on every axis (touching counts).
//   * The memory rule: a node whose split would give all n of its primitives to two or more
//     children stays a leaf (splitting it separates nothing and only copies references).
//   * Layout: a split node gets its eight children appended to nodes as one block at once
//     (child k at firstChild + k); then the children are built in order 0..7, each completely
//     (depth first) before the next. A leaf appends its primitives to primIndices when it is
//     made (primStart = primIndices.size() at that moment, also when it is empty).
//     primCount is the node's n, for interior nodes too. So every correct builder makes the
//     same octree.
Octree buildOctree(const OctreeInput& input, const OctreeOptions& options);

// --- The walk (assignments/a4_octree/octree_walk.cpp) --------------------------------------------
// Revelles' traversal works on a ray whose direction components are all non-negative: a
// negative component is flipped by mirroring the ray about the root's centre, and the child
// indices flipped with it (child k of the mirrored octree is child k ^ mask of the real one).

// Per axis a with std::signbit(ray.direction[a]) (so -0.0 too): origin[a] = (root.lower[a] +
// root.upper[a]) - origin[a], direction[a] = -direction[a], mask |= 4 >> a. tMin and tMax stay.
MirroredRay mirrorRay(const Bounds3f& root, const Ray& ray);

// Where the mirrored ray crosses the root's slabs, per axis a with o = origin[a], d =
// direction[a]: t0 = (root.lower[a] - o) / d, t1 = (root.upper[a] - o) / d; for d == 0 the ray
// runs parallel to the slab: t0 = (o < root.lower[a] ? +inf : -inf), t1 = (o > root.upper[a] ?
// -inf : +inf) (inside the closed slab: -inf .. +inf; outside: never in it).
NodeSpan rootSpan(const Bounds3f& root, const Ray& mirrored);

// The parameters at which the mirrored ray crosses the mid-planes of a node with this box (in
// the mirrored frame) and span: tm[a] = 0.5f * (t0[a] + t1[a]); where direction[a] == 0 that is
// NaN or meaningless, and instead tm[a] = -inf if the origin lies in the node's upper half on a
// (childIndex(origin, box.centre()) has a's bit), +inf if in the lower half.
Vec3 midParameters(const Ray& mirrored, const NodeSpan& span, const Bounds3f& box);

// The first child the ray enters (Revelles' Table 1, with the published erratum: x is bit 4).
// The entry plane is the axis of the largest t0 (ties go to the higher axis: x = y > z enters
// through y, x = z > y and y = z > x through z). For the two other axes b, the bit of b is set
// when tm[b] < that largest t0 (strictly).
int firstNode(const Vec3& t0, const Vec3& tm);

// The child after `current` (Revelles' Table 3), given current's exit parameters t1: the exit
// plane is the axis of the smallest t1 (ties go to the higher axis, as in firstNode); if
// current's bit for that axis is set the ray leaves the parent (kOctreeEnd), else the next
// child is current | that bit.
int nextNode(int current, const Vec3& t1);

// --- Traversal (assignments/a4_octree/octree_traverse.cpp) ---------------------------------------
// mirrorRay, rootSpan, then a recursive walk from the root with the root's box (it is its own
// mirror image) and span. At a node with span (t0, t1):
//   * skip it when min(t1) < ray.tMin (it lies behind the segment: the origin is past it);
//   * a leaf: traversal.enterLeaf(node) once, then each primitive through
//     traversal.intersectOnce(prim, hit) / traversal.occludesOnce(prim) (the mailbox tests a
//     primitive in several leaves once per ray); the walk ends when hit.t <= min(t1) (no later
//     leaf can hold a nearer hit; hit.t starts at ray.tMax);
//   * an interior node: tm = midParameters, k = firstNode(t0, tm); while k != kOctreeEnd: the
//     child's span is (tm[a], t1[a]) on each axis a whose bit k has, (t0[a], tm[a]) on the
//     others; walk nodes[firstChild + (k ^ mask)] with box childBox(box, k); k = nextNode(k,
//     the child's t1).
// The root is walked only when max(t0) <= min(t1), min(t1) >= ray.tMin and max(t0) <= hit.t
// (NaN in the span: a miss).

// Closest hit in (ray.tMin, hit.t]. Returns hit.found().
bool intersectOctree(const Octree& octree, Traversal& traversal, Hit& hit);
// Any hit in (ray.tMin, ray.tMax]: stop at the first primitive that blocks the ray.
bool occludedOctree(const Octree& octree, Traversal& traversal);

}  // namespace rtlab
