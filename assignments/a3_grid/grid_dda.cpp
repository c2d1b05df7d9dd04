// Assignment a3, part 2: the 3D-DDA.               Guide: docs/a3-grid.md#the-3d-dda
//
// Contract (framework/interface/a3_grid.h):
//   * ddaSetup: start in cellOfPoint(grid, ray.at(tEnter)). Per axis, with d the direction:
//       d == 0 (+0 or -0):  step 0, tNext = tDelta = kInfinity;
//       else                step = d < 0 ? -1 : +1,
//                           tNext  = (bounds.lower[a] + (cell[a] + (step > 0 ? 1 : 0))
//                                     * cellWidth[a] - origin[a]) / d,
//                           tDelta = cellWidth[a] / |d|.
//     Keep tExit as given.
//   * ddaStep: axis = the smallest tNext, ties to the higher axis. If tNext[axis] is
//     kInfinity (a zero direction) or > tExit, return false and change nothing. Else cell[axis] += step[axis], tNext[axis] +=
//     tDelta[axis], and return whether cell[axis] is still inside 0 .. resolution - 1.
//
// Hints:
//   * `d < 0` is false for -0.0, but 1.0f / -0.0f is -inf: test d == 0 before anything else.
//   * Move one axis per step, also when two tNext are equal (the ray passes an edge): moving
//     two at once skips a cell that the ray touches.
//   * For step -1 the boundary ahead is the cell's own lower face, cell[a] * width from lower,
//     not (cell[a] - 1) * width.
#include "framework/core/error.h"
#include "framework/interface/a3_grid.h"

namespace rtlab {

DdaState ddaSetup(const UniformGrid& grid, const Ray& ray, float tEnter, float tExit) {
    (void)grid, (void)ray, (void)tEnter, (void)tExit;
    throw NotImplemented("a3 ddaSetup (assignments/a3_grid/grid_dda.cpp)");
}

bool ddaStep(DdaState& state, const std::array<int, 3>& resolution) {
    (void)state, (void)resolution;
    throw NotImplemented("a3 ddaStep (assignments/a3_grid/grid_dda.cpp)");
}

}  // namespace rtlab
