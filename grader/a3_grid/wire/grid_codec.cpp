#include "grader/a3_grid/wire/grid_codec.h"

#include "grader/a3_grid/wire/grid_inputs.h"
#include "grader/wire/index_checks.h"

#include <algorithm>

namespace rtlab::grader {
namespace {

constexpr int32_t kMaxGridResolution = 1024;

}  // namespace

void writeGrid(ByteWriter& out, const UniformGrid& grid) {
    out.put(worker::GridFrame{grid.bounds, grid.resolution, grid.cellWidth, grid.inverseWidth});
    out.putVector(grid.cellStart);
    out.putVector(grid.primIndices);
}

UniformGrid readGrid(ByteReader& in, uint32_t primCount) {
    auto frame = in.get<worker::GridFrame>();
    UniformGrid grid;
    for (int a = 0; a < 3; ++a)
        if (frame.resolution[a] < 1 || frame.resolution[a] > kMaxGridResolution) throw WireError("bad grid resolution");
    grid.bounds = frame.bounds;
    grid.resolution = frame.resolution;
    grid.cellWidth = frame.cellWidth;
    grid.inverseWidth = frame.inverseWidth;
    grid.cellStart = in.getVector<uint32_t>(kMaxStructureEntries);
    grid.primIndices = in.getVector<uint32_t>(kMaxStructureEntries);
    if (grid.cellStart.size() != grid.cellCount() + 1 || grid.cellStart.front() != 0 || grid.cellStart.back() != grid.primIndices.size() ||
        !std::is_sorted(grid.cellStart.begin(), grid.cellStart.end()))
        throw WireError("malformed cell starts");
    checkPrimitiveIds(grid.primIndices, primCount);
    return grid;
}

}  // namespace rtlab::grader
