// Assignment a3 (docs/a3-grid.md): the uniform grid and its 3D-DDA traversal.
// Implemented in assignments/a3_grid/ (yours) and solutions/a3_grid/ (reference).
#pragma once

#include "framework/core/hit.h"
#include "framework/interface/grid.h"
#include "framework/interface/traversal.h"

#include <span>

namespace rtlab {

// --- Building (assignments/a3_grid/grid_build.cpp) ---------------------------------------------

// The lecture's resolution rule. With N primitives and the longest extent E of bounds,
// k = cbrt(C * N) / E cells per unit length (C = options.cellsPerPrimitive, computed in
// double), and resolution[a] = clamp(lround(extent[a] * k), 1, options.maxResolution). A cube
// gets C * N cells; a flat axis gets 1. N = 0 or E = 0 gives {1, 1, 1}.
std::array<int, 3> gridResolution(const Bounds3f& bounds, size_t primCount, const GridOptions& options);

// The cell holding point p: per axis clamp(floor((p[a] - bounds.lower[a]) * inverseWidth[a]),
// 0, resolution[a] - 1), computed in float. A point on an interior boundary belongs to the upper
// cell, a point on the upper face (or outside) to the last cell.
GridCell cellOfPoint(const UniformGrid& grid, const Vec3& p);

// The cells a box overlaps: cellOfPoint(box.lower) .. cellOfPoint(box.upper), inclusive.
CellRange cellRange(const UniformGrid& grid, const Bounds3f& box);

// Fills grid.cellStart and grid.primIndices of a grid whose frame (bounds, resolution, widths)
// is set: primitive i goes into every cell of cellRange(grid, primBounds[i]); each cell lists
// its primitives in increasing index order. A primitive whose box is not isPlaceable goes
// nowhere.
void fillGridCells(UniformGrid& grid, std::span<const Bounds3f> primBounds);

// --- Walking (assignments/a3_grid/grid_dda.cpp) ------------------------------------------------

// The DDA's start, for a ray whose segment inside the grid is [tEnter, tExit] (tEnter from
// the slab test of the grid's bounds). Per axis a, with d = ray.direction[a]:
//   cell     = cellOfPoint(grid, ray.origin + tEnter * ray.direction)
//   d == 0 (either sign):  step = 0, tNext = tDelta = +inf
//   otherwise:             step = d < 0 ? -1 : +1,
//                          tNext  = (bounds.lower[a] + (cell[a] + (step > 0)) * cellWidth[a]
//                                    - ray.origin[a]) / d,
//                          tDelta = cellWidth[a] / |d|
// and tExit as given.
DdaState ddaSetup(const UniformGrid& grid, const Ray& ray, float tEnter, float tExit);

// One step to the next cell: the axis with the smallest tNext (ties go to the HIGHER axis
// index, so x = y < z steps y). If that tNext is infinite (the ray does not move at all) or
// beyond state.tExit the walk is over: return false and leave the state as it is. Otherwise move cell one step along that axis, add tDelta
// to its tNext and return whether the new cell is inside the grid.
bool ddaStep(DdaState& state, const std::array<int, 3>& resolution);

// --- Traversal (assignments/a3_grid/grid_traverse.cpp) -----------------------------------------
// Through the Traversal context: traversal.hitsBox(grid.bounds, ...) once, then
// traversal.countCellStep() for every cell entered and traversal.intersectOnce(prim, hit) /
// traversal.occludesOnce(prim) for its primitives (the mailbox tests each primitive once).

// Closest hit: walk the cells front to back; a hit found in a cell is final only once it lies
// no farther than where the ray leaves that cell (a primitive reaching into later cells may be
// hit beyond it, and a nearer one may wait there). Returns hit.found().
bool intersectGrid(const UniformGrid& grid, Traversal& traversal, Hit& hit);
// Any hit in (ray.tMin, ray.tMax]: stop at the first primitive that blocks the ray.
bool occludedGrid(const UniformGrid& grid, Traversal& traversal);

// --- Beyond the lecture (assignments/a3_grid/two_level_grid.cpp; optional, not graded) --------

// The top grid by gridResolution's rule with `top`; a top cell with more than refineAbove
// primitives gets a child grid over the cell's box (shrunk to its primitives' bounds) by the
// same rule with `child`, for those primitives alone.
TwoLevelGrid buildTwoLevelGrid(std::span<const Bounds3f> primBounds, const GridOptions& top, const GridOptions& child,
                               uint32_t refineAbove);
bool intersectTwoLevelGrid(const TwoLevelGrid& grid, Traversal& traversal, Hit& hit);
bool occludedTwoLevelGrid(const TwoLevelGrid& grid, Traversal& traversal);

// --- Provided by the framework (framework/accel/grid_frame.cpp) ---------------------------------

// A grid over primBounds (the union of the placeable ones) with
// gridResolution's cells and the widths set, its cells not yet filled.
UniformGrid gridFrame(std::span<const Bounds3f> primBounds, const GridOptions& options);
// The same over a given box: the frame of a child grid.
UniformGrid gridFrameOver(const Bounds3f& bounds, size_t primCount, const GridOptions& options);
// The box of a cell: lower + cell * cellWidth .. lower + (cell + 1) * cellWidth, in float.
Bounds3f gridCellBox(const UniformGrid& grid, const GridCell& cell);

}  // namespace rtlab
