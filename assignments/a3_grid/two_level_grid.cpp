// Assignment a3, beyond the lecture: a two-level grid (optional, not graded).
//                                                  Guide: docs/a3-grid.md#beyond-the-lecture-two-level-grids
//
// Contract (framework/interface/a3_grid.h, framework/interface/grid.h):
//   * buildTwoLevelGrid: the top grid as for the uniform grid with the options `top`
//     (gridFrame, fillGridCells); then for every top cell with more than refineAbove primitives
//     a child grid, gridFrameOver(the cell's box shrunk to its primitives' bounds, their count, child),
//     filled with those primitives (fillGridCells numbers them 0..n-1: map them back to scene
//     ids), and childOf[cell] = its index in children (kNoChild elsewhere).
//   * intersectTwoLevelGrid / occludedTwoLevelGrid: walk the top grid as intersectGrid does;
//     in a cell with a child, walk the child over the part of the ray inside both the child's
//     box and the top cell, with the same rule for final hits. Test primitives through
//     traversal.intersectOnce / occludesOnce: the mailbox spans both levels.
// Try it with `rtlab render --accel grid2` on scenes/ or `rtlab bench --scenes stadium`.
#include "framework/core/error.h"
#include "framework/interface/a3_grid.h"

namespace rtlab {

TwoLevelGrid buildTwoLevelGrid(std::span<const Bounds3f> primBounds, const GridOptions& top, const GridOptions& child,
                               uint32_t refineAbove) {
    (void)primBounds, (void)top, (void)child, (void)refineAbove;
    throw NotImplemented("a3 buildTwoLevelGrid (assignments/a3_grid/two_level_grid.cpp)");
}

bool intersectTwoLevelGrid(const TwoLevelGrid& grid, Traversal& traversal, Hit& hit) {
    (void)grid, (void)traversal, (void)hit;
    throw NotImplemented("a3 intersectTwoLevelGrid (assignments/a3_grid/two_level_grid.cpp)");
}

bool occludedTwoLevelGrid(const TwoLevelGrid& grid, Traversal& traversal) {
    (void)grid, (void)traversal;
    throw NotImplemented("a3 occludedTwoLevelGrid (assignments/a3_grid/two_level_grid.cpp)");
}

}  // namespace rtlab
