// A uniform grid as the grader's StructureView: a root over the grid's bounds whose children are
// its cells, in cellIndex order, each a leaf listing the cell's primitives.
#pragma once

#include "framework/accel/structure_view.h"
#include "framework/interface/grid.h"

#include <span>

namespace rtlab {

// frame gives the bounds, resolution and widths; the cells are cellStart and primIndices in
// UniformGrid's compact layout (frame's own lists may be empty).
StructureView gridStructureView(const UniformGrid& frame, std::span<const uint32_t> cellStart,
                                std::span<const uint32_t> primIndices);

}  // namespace rtlab
