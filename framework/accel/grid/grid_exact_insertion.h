// The uniform grid's optional exact insertion (docs/a3-grid.md#exact-insertion): after the
// cells are filled by bounding boxes (a3's fillGridCells), each triangle is kept only in the
// cells its surface overlaps, by a4's triangleOverlapsBox on the cell's box grown as the
// octree's (insertionBox), so that rounding never drops a triangle that touches the cell.
// Spheres keep their box's cells.
#pragma once

#include "framework/accel/primitive_set.h"
#include "framework/interface/grid.h"
#include "framework/interface/octree.h"

namespace rtlab {

// Drops from every cell the triangles whose surface does not overlap the cell's box; the cells'
// lists stay in increasing order.
void keepOverlappingTriangles(UniformGrid& grid, const PrimitiveSet& primitives);

}  // namespace rtlab
