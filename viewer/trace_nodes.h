// Which node, cell or leaf each operation of a trace was about (docs/viewer.md#a-rays-way). The
// Traversal context is told a node only by enterLeaf; the rest is recovered from what it records:
//  * a box test names its box: the node with exactly those bounds (the first, in tree order);
//  * a leaf entry names its node;
//  * the k-th cell step of a grid walk is the k-th cell of the walk's own cell list, when one is
//    given (a3's DDA run on the same ray);
//  * a run of primitive tests and mailbox repeats after any other step is the list of a leaf or
//    cell: the node whose primitives are exactly that run, the nearest along the ray after the
//    one before when several are;
//  * a plane step names nothing (the leaf after it does).
// And where two traces of the same ray part: the first step that differs.
#pragma once

#include "framework/accel/structure_view.h"
#include "framework/core/ray.h"
#include "framework/interface/grid.h"
#include "framework/interface/traversal_trace.h"

#include <cstdint>
#include <vector>

namespace rtlab::viewer {

inline constexpr uint32_t kUnresolved = 0xffffffffu;

// Per operation: an index into view.nodes, or kUnresolved. cells: the grid cells of this ray's
// walk in order (empty: none known); used when the view is a grid (a root whose children are
// the resolution's cells in cellIndex order).
std::vector<uint32_t> resolveTraceNodes(const StructureView& view, const TraversalTrace& trace, const Ray& ray,
                                        const std::vector<GridCell>& cells, const std::array<int, 3>& resolution);

// The first operation at which the two traces differ (kind, index, hit; a box test's box bit for
// bit), or -1 when they are the same. A trace that is a prefix of the other differs where it ends.
int64_t firstDifference(const TraversalTrace& a, const TraversalTrace& b);

}  // namespace rtlab::viewer
