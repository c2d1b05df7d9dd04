// a3's uniform grid as the framework drives it: built over a primitive set and queried, each
// through the student's functions. The accelerator (grid_accelerator.h: render, hits, the bench)
// and the grader's worker (grader/a3_grid/worker/grid_tasks.cpp) both call these, so what is
// graded is what renders.
#pragma once

#include "framework/accel/primitive_set.h"
#include "framework/interface/grid.h"
#include "framework/interface/traversal.h"

namespace rtlab {

// Which cells hold a triangle: every cell its box overlaps (a3's fillGridCells), or then only
// those its surface overlaps (a4's triangle-box test, grid_exact_insertion.h).
enum class GridInsertion { Box, Exact };

struct GridAdapter {
    // The framework's gridFrame (with a3's gridResolution), then a3's fillGridCells.
    static UniformGrid build(const PrimitiveSet& primitives, const GridOptions& options, GridInsertion insertion);
    // Closest hit in (ray.tMin, hit.t]: a3's intersectGrid.
    static bool intersect(const UniformGrid& grid, Traversal& traversal, Hit& hit);
    // Any hit: a3's occludedGrid.
    static bool occluded(const UniformGrid& grid, Traversal& traversal);
};

}  // namespace rtlab
