// Reference solution: closest-hit and any-hit traversal of the uniform grid
// (docs/a3-grid.md#traversal).
#include "framework/interface/a3_grid.h"

#include <algorithm>

namespace rtlab {

namespace {

// Where the ray's segment lies inside the grid, or false if it misses the grid.
bool segmentInGrid(const UniformGrid& grid, Traversal& traversal, float tMax, DdaState* state) {
    float tEnter;
    if (grid.primIndices.empty() || !traversal.hitsBox(grid.bounds, tMax, &tEnter)) return false;
    // The slab test's far distance, recomputed: the walk stops at tMax or at the grid's exit,
    // whichever comes first; ddaStep's in-range check ends it at the exit in any case.
    *state = ddaSetup(grid, traversal.ray(), tEnter, tMax);
    return true;
}

std::span<const uint32_t> primitivesOf(const UniformGrid& grid, const GridCell& cell) {
    size_t c = grid.cellIndex(cell);
    return {grid.primIndices.data() + grid.cellStart[c], grid.cellStart[c + 1] - grid.cellStart[c]};
}

}  // namespace

bool intersectGrid(const UniformGrid& grid, Traversal& traversal, Hit& hit) {
    DdaState state;
    if (!segmentInGrid(grid, traversal, hit.t, &state)) return false;
    do {
        traversal.countCellStep();
        for (uint32_t prim : primitivesOf(grid, state.cell)) traversal.intersectOnce(prim, hit);
        // The ray leaves this cell at the nearest tNext: a hit up to there cannot be beaten by
        // anything in a later cell. A hit beyond it stays a candidate (its primitive reaches
        // into later cells), and the mailbox keeps it from being tested again there.
        float cellExit = std::min({state.tNext[0], state.tNext[1], state.tNext[2]});
        if (hit.t <= cellExit) break;
        state.tExit = std::min(state.tExit, hit.t);
    } while (ddaStep(state, grid.resolution));
    return hit.found();
}

bool occludedGrid(const UniformGrid& grid, Traversal& traversal) {
    DdaState state;
    if (!segmentInGrid(grid, traversal, traversal.ray().tMax, &state)) return false;
    do {
        traversal.countCellStep();
        for (uint32_t prim : primitivesOf(grid, state.cell))
            if (traversal.occludesOnce(prim)) return true;
    } while (ddaStep(state, grid.resolution));
    return false;
}

}  // namespace rtlab
