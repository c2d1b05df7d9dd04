// Reference solution: the grid's resolution, cell lookup and filling (docs/a3-grid.md#building).
#include "framework/interface/a3_grid.h"

#include <algorithm>
#include <cmath>

namespace rtlab {

std::array<int, 3> gridResolution(const Bounds3f& bounds, size_t primCount, const GridOptions& options) {
    Vec3 extent = bounds.diagonal();
    double longest = std::max({double(extent.x), double(extent.y), double(extent.z)});
    // !(longest > 0) also catches an empty box (negative extent) and NaN.
    if (primCount == 0 || !(longest > 0.0)) return {1, 1, 1};
    // cbrt(C N) cells along the longest axis; the others in proportion, so cells are cubes.
    double cellsPerUnit = std::cbrt(options.cellsPerPrimitive * double(primCount)) / longest;
    std::array<int, 3> resolution;
    for (int a = 0; a < 3; ++a) {
        long cells = std::lround(double(extent[a]) * cellsPerUnit);
        resolution[a] = int(std::clamp<long>(cells, 1, options.maxResolution));
    }
    return resolution;
}

GridCell cellOfPoint(const UniformGrid& grid, const Vec3& p) {
    GridCell cell;
    for (int a = 0; a < 3; ++a) {
        // floor, not truncation: a point just below the grid must clamp to cell 0, not round
        // towards it from -0.9 to 0 by accident of the cast (and NaN clamps to 0 as well).
        float offset = std::floor((p[a] - grid.bounds.lower[a]) * grid.inverseWidth[a]);
        cell[a] = offset >= float(grid.resolution[a] - 1) ? grid.resolution[a] - 1 : offset > 0.0f ? int(offset) : 0;
    }
    return cell;
}

CellRange cellRange(const UniformGrid& grid, const Bounds3f& box) {
    return {cellOfPoint(grid, box.lower), cellOfPoint(grid, box.upper)};
}

void fillGridCells(UniformGrid& grid, std::span<const Bounds3f> primBounds) {
    // Two passes over the primitives: count the references of each cell, turn the counts into
    // start offsets, then write each primitive into its cells. Visiting primitives in index
    // order leaves every cell's list sorted.
    grid.cellStart.assign(grid.cellCount() + 1, 0);
    auto forEachCell = [&](const Bounds3f& box, auto&& visit) {
        CellRange range = cellRange(grid, box);
        for (int z = range.lower[2]; z <= range.upper[2]; ++z)
            for (int y = range.lower[1]; y <= range.upper[1]; ++y)
                for (int x = range.lower[0]; x <= range.upper[0]; ++x) visit(grid.cellIndex({x, y, z}));
    };
    for (const Bounds3f& box : primBounds)
        if (isPlaceable(box)) forEachCell(box, [&](size_t c) { ++grid.cellStart[c + 1]; });
    for (size_t c = 0; c < grid.cellCount(); ++c) grid.cellStart[c + 1] += grid.cellStart[c];

    grid.primIndices.assign(grid.cellStart.back(), 0);
    std::vector<uint32_t> next(grid.cellStart.begin(), grid.cellStart.end() - 1);
    for (uint32_t prim = 0; prim < primBounds.size(); ++prim)
        if (isPlaceable(primBounds[prim])) forEachCell(primBounds[prim], [&](size_t c) { grid.primIndices[next[c]++] = prim; });
}

}  // namespace rtlab
