#include "framework/accel/grid/grid_adapter.h"

#include "framework/accel/grid/grid_exact_insertion.h"
#include "framework/interface/a3_grid.h"

namespace rtlab {

UniformGrid GridAdapter::build(const PrimitiveSet& primitives, const GridOptions& options, GridInsertion insertion) {
    UniformGrid grid = gridFrame(primitives.allBounds(), options);
    fillGridCells(grid, primitives.allBounds());
    if (insertion == GridInsertion::Exact) keepOverlappingTriangles(grid, primitives);
    return grid;
}

bool GridAdapter::intersect(const UniformGrid& grid, Traversal& traversal, Hit& hit) { return intersectGrid(grid, traversal, hit); }

bool GridAdapter::occluded(const UniformGrid& grid, Traversal& traversal) { return occludedGrid(grid, traversal); }

}  // namespace rtlab
