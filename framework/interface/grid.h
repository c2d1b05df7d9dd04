// The uniform grid of assignment a3 (docs/a3-grid.md): the scene's bounds cut into
// resolution[0] x resolution[1] x resolution[2] equal cells, each listing the primitives that
// overlap it. Cells are stored as one compact array (the "compact grid" of Lagae and Dutre
// 2008): cell c holds primIndices[cellStart[c] .. cellStart[c + 1]).
#pragma once

#include "framework/core/bounds.h"

#include <array>
#include <cstdint>
#include <vector>

namespace rtlab {

// Integer cell coordinates (x, y, z), each in 0 .. resolution - 1 for a cell of the grid.
using GridCell = std::array<int, 3>;

struct GridOptions {
    double cellsPerPrimitive = 27.0;  // C of the lecture's rule: cells ~= C * N (1 .. 1000)
    int maxResolution = 64;           // cap on the cells along any axis (1 .. 1024)
};

struct UniformGrid {
    Bounds3f bounds;                   // union of the primitives' bounds
    std::array<int, 3> resolution{1, 1, 1};
    Vec3 cellWidth{0.0f};              // bounds extent / resolution, per axis
    Vec3 inverseWidth{0.0f};           // resolution / extent, 0 on a flat axis
    std::vector<uint32_t> cellStart;   // cellCount() + 1 entries, cellStart[0] = 0
    std::vector<uint32_t> primIndices;

    size_t cellCount() const { return size_t(resolution[0]) * resolution[1] * resolution[2]; }
    // x varies fastest, then y, then z.
    size_t cellIndex(const GridCell& c) const {
        return (size_t(c[2]) * resolution[1] + c[1]) * resolution[0] + c[0];
    }
};

// Beyond the lecture: a two-level grid. The top grid is built by the usual rule; each top cell
// holding more than a few primitives is refined by a grid of its own, over that cell, with the
// same rule applied to the primitives of that cell alone. Scenes whose geometry is concentrated
// in a small part of the box (the teapot in a stadium) get small cells where the geometry is.
struct TwoLevelGrid {
    static constexpr uint32_t kNoChild = 0xffffffffu;
    UniformGrid top;
    std::vector<uint32_t> childOf;     // per top cell: index into children, or kNoChild
    std::vector<UniformGrid> children;
};

// The cells a box overlaps: every cell with lower[a] <= cell[a] <= upper[a] on each axis.
struct CellRange {
    GridCell lower;
    GridCell upper;
};

// Where the 3D-DDA stands: the current cell, the direction of travel per axis, the ray
// parameter at which the ray crosses the next cell boundary per axis, the parameter distance
// between two boundaries per axis, and where the walk ends.
struct DdaState {
    GridCell cell;
    std::array<int, 3> step;  // +1, -1, or 0 for a zero direction component
    Vec3 tNext;               // +inf on an axis with step 0
    Vec3 tDelta;              // +inf on an axis with step 0
    float tExit;              // the ray leaves the grid (or its tMax is reached) here
};

}  // namespace rtlab
