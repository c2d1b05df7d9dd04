// The cells of a uniform grid filled by a cache-aware counting sort: the same cellStart and
// primIndices as a3's fillGridCells (framework/interface/a3_grid.h), bit for bit, in a fraction
// of its time on big scenes (docs/performance.md#the-tuned-grid).
//
// The textbook fill counts and then scatters every reference straight into its cell. On a
// million triangles both passes jump across megabytes of counters and lists at random, and each
// jump is a cache miss. Here the references are first dealt into one run per z layer of cells,
// written front to back, and then each layer is counted and scattered on its own, with its
// counters and its part of the lists small enough to stay in cache.
#pragma once

#include "fast/uninitialised_allocator.h"
#include "framework/interface/grid.h"

#include <span>
#include <vector>

namespace rtlab {

// An array whose elements are written before they are read.
template <typename T>
using UninitialisedVector = std::vector<T, UninitialisedAllocator<T>>;

// A grid's compact cells (the layout of UniformGrid): cell c lists
// primIndices[cellStart[c] .. cellStart[c + 1]).
struct GridCells {
    UninitialisedVector<uint32_t> cellStart;
    UninitialisedVector<uint32_t> primIndices;
};

// The cells of a grid whose frame (bounds, resolution, widths) is set: primitive i in every cell
// of a3's cellRange of primBounds[i], each cell's list in increasing index order, a box that is
// not isPlaceable nowhere.
GridCells sortIntoCells(const UniformGrid& frame, std::span<const Bounds3f> primBounds);

}  // namespace rtlab
