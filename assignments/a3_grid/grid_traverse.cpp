// Assignment a3, part 3: traversing the grid.      Guide: docs/a3-grid.md#traversal
//
// Contract (framework/interface/a3_grid.h):
//   Test the grid's bounds once with traversal.hitsBox(grid.bounds, tMax, &tEnter) (tMax is
//   hit.t for intersectGrid, ray.tMax for occludedGrid); on a miss, or an empty grid, return
//   false. Then ddaSetup(grid, traversal.ray(), tEnter, tMax) and, for every cell the walk
//   enters (the first one included), traversal.countCellStep() and each of its primitives
//   through traversal.intersectOnce(prim, hit) / traversal.occludesOnce(prim).
//   * intersectGrid: after a cell, stop if hit.t <= the smallest tNext (where the ray leaves
//     the cell); otherwise go on with ddaStep until it returns false. Return hit.found().
//   * occludedGrid: true at the first primitive that blocks the ray.
//
// Hints:
//   * Returning at the first cell with any hit is the classic mistake: a large triangle
//     listed in this cell may be hit far beyond it, behind a small one in the next cell.
//   * A hit farther than the cell is not lost when you move on: it stays in `hit`, and the
//     mailbox stops the same primitive from being tested again in the next cells.
#include "framework/core/error.h"
#include "framework/interface/a3_grid.h"

namespace rtlab {

bool intersectGrid(const UniformGrid& grid, Traversal& traversal, Hit& hit) {
    (void)grid, (void)traversal, (void)hit;
    throw NotImplemented("a3 intersectGrid (assignments/a3_grid/grid_traverse.cpp)");
}

bool occludedGrid(const UniformGrid& grid, Traversal& traversal) {
    (void)grid, (void)traversal;
    throw NotImplemented("a3 occludedGrid (assignments/a3_grid/grid_traverse.cpp)");
}

}  // namespace rtlab
