// The frame of a uniform grid (framework/interface/a3_grid.h): its bounds, the resolution the
// student's gridResolution chooses, and the cell widths every later step divides by. A cell's
// box is in grid_cell_box.cpp.
#include "framework/interface/a3_grid.h"

namespace rtlab {

UniformGrid gridFrame(std::span<const Bounds3f> primBounds, const GridOptions& options) {
    UniformGrid grid;
    size_t usable = 0;
    for (const Bounds3f& box : primBounds)
        if (isPlaceable(box)) {
            grid.bounds.extend(box);
            ++usable;
        }
    if (usable == 0) grid.bounds = Bounds3f(Vec3(0.0f));
    return gridFrameOver(grid.bounds, usable, options);
}

UniformGrid gridFrameOver(const Bounds3f& bounds, size_t primCount, const GridOptions& options) {
    UniformGrid grid;
    grid.bounds = bounds;
    grid.resolution = gridResolution(bounds, primCount, options);
    Vec3 extent = grid.bounds.diagonal();
    for (int a = 0; a < 3; ++a) {
        grid.cellWidth[a] = extent[a] / float(grid.resolution[a]);
        // A flat axis has one cell of width 0: every point maps to it.
        grid.inverseWidth[a] = extent[a] > 0.0f ? float(grid.resolution[a]) / extent[a] : 0.0f;
    }
    return grid;
}

}  // namespace rtlab
