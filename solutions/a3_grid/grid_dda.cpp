// Reference solution: the 3D-DDA of Amanatides and Woo (1987), set up and stepped
// (docs/a3-grid.md#the-3d-dda).
#include "framework/interface/a3_grid.h"

#include <cmath>

namespace rtlab {

DdaState ddaSetup(const UniformGrid& grid, const Ray& ray, float tEnter, float tExit) {
    DdaState state;
    state.cell = cellOfPoint(grid, ray.at(tEnter));
    state.tExit = tExit;
    for (int a = 0; a < 3; ++a) {
        float d = ray.direction[a];
        // Both zeros first: -0.0 < 0 is false, but 1/-0.0 is -inf, and a negative tDelta would
        // make this axis look like the nearest crossing forever.
        if (d == 0.0f) {
            state.step[a] = 0;
            state.tNext[a] = state.tDelta[a] = kInfinity;
            continue;
        }
        state.step[a] = d < 0.0f ? -1 : 1;
        // The boundary ahead: the cell's upper face when moving up, its lower face when down.
        float boundary = grid.bounds.lower[a] + float(state.cell[a] + (state.step[a] > 0 ? 1 : 0)) * grid.cellWidth[a];
        state.tNext[a] = (boundary - ray.origin[a]) / d;
        state.tDelta[a] = grid.cellWidth[a] / std::abs(d);
    }
    return state;
}

bool ddaStep(DdaState& state, const std::array<int, 3>& resolution) {
    // The nearest crossing; `<=` hands ties to the higher axis (x = y < z steps y), and only
    // one axis moves per step, so no cell is skipped when the ray passes through an edge.
    int axis = 0;
    for (int a = 1; a < 3; ++a)
        if (state.tNext[a] <= state.tNext[axis]) axis = a;
    if (state.tNext[axis] == kInfinity) return false;  // a zero direction: the ray does not move
    if (state.tNext[axis] > state.tExit) return false;
    state.cell[axis] += state.step[axis];
    state.tNext[axis] += state.tDelta[axis];
    return state.cell[axis] >= 0 && state.cell[axis] < resolution[axis];
}

}  // namespace rtlab
