// Assignment a1 (docs/a1-bvh.md): build a BVH with simple split heuristics and traverse it.
// Implemented in assignments/a1_bvh/ (yours) and solutions/a1_bvh/ (reference).
#pragma once

#include "framework/interface/traversal.h"
#include "framework/core/hit.h"
#include "framework/interface/bvh.h"

namespace rtlab {

// --- Building (assignments/a1_bvh/bvh_build.cpp) ---------------------------------------------

// Builds the BVH over prims (any order; the function may reorder them). For each node: compute
// its NodeInfo, call splitNode (below); 0 means "make a leaf", k > 0 means the first k
// primitives of the (reordered) span go to the first child, the rest to the second. An
// interior node's axis is maxComponentIndex(second.bounds.centre() - first.bounds.centre()).
// A leaf holds at most 65535 primitives: a bigger one is split with splitEqualCounts instead.
Bvh buildBvh(std::vector<BuildPrimitive> prims, const BvhOptions& options);

// --- Split heuristics (assignments/a1_bvh/bvh_splits.cpp) -------------------------------------
// Each reorders prims so the left part comes first and returns its size k, 0 < k < prims.size().
// Called only with at least two primitives whose centroids are not all equal.
// Ties between equal centroid coordinates are broken by BuildPrimitive::index, so every
// correct implementation builds exactly the same tree.

// The lecture's heuristic: longest axis of the node's bounds, split at the median object
// (k = n / 2 after ordering by (centroid[axis], index)).
uint32_t splitMedian(std::span<BuildPrimitive> prims, const NodeInfo& node);
// Longest centroid axis, split at the midpoint of the centroid bounds: left are the
// primitives with centroid[axis] < mid. Falls back to splitEqualCounts if a side is empty.
uint32_t splitMiddle(std::span<BuildPrimitive> prims, const NodeInfo& node);
// Longest centroid axis, equal counts: k = n / 2 after ordering by (centroid[axis], index).
uint32_t splitEqualCounts(std::span<BuildPrimitive> prims, const NodeInfo& node);

// --- Traversal (assignments/a1_bvh/bvh_traverse.cpp) ------------------------------------------
// All three go through the Traversal context: traversal.hitsBox(...) for a node,
// traversal.intersect(prim, hit) / traversal.occludes(prim) for a primitive.

// Closest hit, written exactly as the lecture's recursive pseudocode. hit.t starts at
// ray.tMax and shrinks with every closer hit found. Returns hit.found().
bool intersectBvhRecursive(const Bvh& bvh, Traversal& traversal, Hit& hit);
// Closest hit, iterative with a fixed-size stack: near child first, and a child whose entry
// distance is beyond the closest hit so far is skipped.
bool intersectBvh(const Bvh& bvh, Traversal& traversal, Hit& hit);
// Any hit in (ray.tMin, ray.tMax]: stop at the first primitive that blocks the ray.
bool occludedBvh(const Bvh& bvh, Traversal& traversal);

// --- Provided by the framework (framework/accel/bvh_split.cpp) ---------------------------------

// Applies the shared rules (one primitive, zero centroid extent or depth >= kMaxBvhDepth - 1:
// leaf; median, middle and equal counts: leaf when n <= maxLeaf), then calls the split
// function of options.method. Returns 0 for a leaf, else the size of the left part. depth is
// 0 at the root.
uint32_t splitNode(std::span<BuildPrimitive> prims, const NodeInfo& node, int depth,
                   const BvhOptions& options);

// Node and centroid bounds of a primitive range.
NodeInfo describeNode(std::span<const BuildPrimitive> prims);

// The deepest BVH the builders can produce and the traversal stacks must hold: leaves are
// forced at this depth (docs/a1-bvh.md, "Stack depth").
inline constexpr int kMaxBvhDepth = 64;

}  // namespace rtlab
