#include "grader/a3_grid/given_grid.h"
#include "grader/a3_grid/grid_oracle.h"
#include "grader/a3_grid/wire/grid_codec.h"

namespace rtlab::grader {

GivenStructure givenGrid(const Scene& scene, uint64_t key) {
    std::vector<Bounds3f> primBounds;
    for (uint32_t i = 0; i < scene.primitiveCount(); ++i) primBounds.push_back(scene.primitiveBounds(i));
    worker::GridFrame frame = expectedFrame(primBounds, GridOptions{});
    UniformGrid grid;
    grid.bounds = frame.bounds;
    grid.resolution = frame.resolution;
    grid.cellWidth = frame.cellWidth;
    grid.inverseWidth = frame.inverseWidth;

    GivenStructure given;
    LeafList& cells = given.leaves;
    cells.prims.resize(grid.cellCount());
    for (int z = 0; z < grid.resolution[2]; ++z)
        for (int y = 0; y < grid.resolution[1]; ++y)
            for (int x = 0; x < grid.resolution[0]; ++x) {
                // The contract's cell box (a3_grid.h), computed here: the framework's
                // gridCellBox lives beside code that calls the student's functions.
                Vec3 lower = grid.bounds.lower + Vec3(float(x), float(y), float(z)) * grid.cellWidth;
                cells.boxes.emplace_back(lower, lower + grid.cellWidth);
            }
    for (uint32_t prim = 0; prim < primBounds.size(); ++prim) {
        if (!isPlaceable(primBounds[prim])) continue;
        GridCell lo = expectedCell(frame, primBounds[prim].lower), hi = expectedCell(frame, primBounds[prim].upper);
        for (int z = lo[2]; z <= hi[2]; ++z)
            for (int y = lo[1]; y <= hi[1]; ++y)
                for (int x = lo[0]; x <= hi[0]; ++x) cells.prims[grid.cellIndex({x, y, z})].push_back(prim);
    }
    leaveOut(cells, scene.primitiveCount(), key, false);
    grid.cellStart.push_back(0);
    for (const auto& list : cells.prims) {
        grid.primIndices.insert(grid.primIndices.end(), list.begin(), list.end());
        grid.cellStart.push_back(uint32_t(grid.primIndices.size()));
    }
    ByteWriter out;
    writeGrid(out, grid);
    given.encoded = std::move(out.bytes());
    return given;
}

}  // namespace rtlab::grader
