// Assignment a3, part 1: the grid's cells.         Guide: docs/a3-grid.md#building
//
// Contract (framework/interface/a3_grid.h, framework/interface/grid.h):
//   * gridResolution: k = cbrt(C * N) / longest extent, computed in double;
//     resolution[a] = clamp(lround(extent[a] * k), 1, options.maxResolution);
//     {1, 1, 1} when N == 0 or the box has no extent.
//   * cellOfPoint: per axis clamp(floor((p[a] - bounds.lower[a]) * inverseWidth[a]), 0,
//     resolution[a] - 1), in float. NaN goes to cell 0.
//   * cellRange: cellOfPoint(box.lower) .. cellOfPoint(box.upper), both ends included.
//   * fillGridCells: grid.cellStart has cellCount() + 1 entries (cellStart[0] = 0); cell c
//     lists primIndices[cellStart[c] .. cellStart[c+1]), in increasing primitive order.
//     Primitive i goes into every cell of cellRange(grid, primBounds[i]) unless
//     !isPlaceable(primBounds[i]). Use grid.cellIndex({x, y, z}).
//
// Hints:
//   * Casting a negative float to int truncates towards zero: -0.5 becomes 0, not -1.
//     floor first, then clamp (and clamp before casting: a huge float does not fit an int).
//   * Fill in two passes: count the primitives of each cell, turn the counts into running
//     sums (that is cellStart), then write each primitive at its cell's next free slot.
#include "framework/core/error.h"
#include "framework/interface/a3_grid.h"

namespace rtlab {

std::array<int, 3> gridResolution(const Bounds3f& bounds, size_t primCount, const GridOptions& options) {
    (void)bounds, (void)primCount, (void)options;
    throw NotImplemented("a3 gridResolution (assignments/a3_grid/grid_build.cpp)");
}

GridCell cellOfPoint(const UniformGrid& grid, const Vec3& p) {
    (void)grid, (void)p;
    throw NotImplemented("a3 cellOfPoint (assignments/a3_grid/grid_build.cpp)");
}

CellRange cellRange(const UniformGrid& grid, const Bounds3f& box) {
    (void)grid, (void)box;
    throw NotImplemented("a3 cellRange (assignments/a3_grid/grid_build.cpp)");
}

void fillGridCells(UniformGrid& grid, std::span<const Bounds3f> primBounds) {
    (void)grid, (void)primBounds;
    throw NotImplemented("a3 fillGridCells (assignments/a3_grid/grid_build.cpp)");
}

}  // namespace rtlab
