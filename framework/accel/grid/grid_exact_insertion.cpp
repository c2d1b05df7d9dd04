#include "framework/accel/grid/grid_exact_insertion.h"

#include "framework/interface/a3_grid.h"
#include "framework/interface/a4_octree.h"

namespace rtlab {

void keepOverlappingTriangles(UniformGrid& grid, const PrimitiveSet& primitives) {
    // Compacts the lists in place: a cell's kept primitives move down to where the previous
    // cell's kept ones end, so one pass rewrites both arrays.
    uint32_t kept = 0;
    for (int z = 0; z < grid.resolution[2]; ++z)
        for (int y = 0; y < grid.resolution[1]; ++y)
            for (int x = 0; x < grid.resolution[0]; ++x) {
                size_t c = grid.cellIndex({x, y, z});
                Bounds3f box = insertionBox(gridCellBox(grid, {x, y, z}));
                uint32_t begin = grid.cellStart[c], end = grid.cellStart[c + 1];
                grid.cellStart[c] = kept;
                for (uint32_t i = begin; i < end; ++i) {
                    uint32_t prim = grid.primIndices[i];
                    bool overlaps = true;
                    if (prim < primitives.triangleCount()) {
                        const std::array<Vec3, 3>& t = primitives.triangle(prim);
                        overlaps = triangleOverlapsBox(t[0], t[1], t[2], box);
                    }
                    if (overlaps) grid.primIndices[kept++] = prim;
                }
            }
    grid.cellStart.back() = kept;
    grid.primIndices.resize(kept);
}

}  // namespace rtlab
