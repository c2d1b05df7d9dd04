// The grader's own answers for a3's pinned rules (framework/interface/a3_grid.h), written from
// the contract: the resolution rule, the cell of a point, and the cells a ray passes through,
// the last computed in double from the exact boundary crossings.
#pragma once

#include "framework/core/ray.h"
#include "framework/interface/grid.h"
#include "grader/a3_grid/wire/grid_inputs.h"

#include <optional>
#include <span>
#include <vector>

namespace rtlab::grader {

std::array<int, 3> expectedResolution(const Bounds3f& bounds, uint64_t primCount, const GridOptions& options);
GridCell expectedCell(const worker::GridFrame& frame, const Vec3& p);
// The frame gridFrame builds over these boxes with this resolution rule.
worker::GridFrame expectedFrame(std::span<const Bounds3f> primBounds, const GridOptions& options);
// A frame over bounds with the given resolution, widths as gridFrame sets them.
worker::GridFrame frameOf(const Bounds3f& bounds, const std::array<int, 3>& resolution);

// The cells the segment [tEnter, tExit] of ray passes through, front to back, from the exact
// crossing parameters; nullopt when two crossings, a crossing and an end, or the start point and
// a boundary lie so close that float rounding may order them either way.
std::optional<std::vector<GridCell>> exactCellWalk(const worker::GridFrame& frame, const Ray& ray, float tEnter, float tExit);

}  // namespace rtlab::grader
