// a3's uniform grid, tuned (--accel fastgrid, docs/performance.md#the-tuned-grid): the same
// frame (gridFrame, the lecture's resolution rule) and the same cells, bit for bit, as the
// textbook `grid`, filled by a cache-aware counting sort (grid_cell_sort.h) and walked with a3's
// 3D-DDA, the triangles of a cell tested four at a time (triangle_packet.h).
//
// The walk needs no mailbox. A primitive's cells form a box of cells, and the DDA never steps
// backwards along an axis, so the cells of one box that a ray visits are consecutive in its
// walk: a primitive listed in the current cell was tested already exactly when the previous
// cell lists it too. Both lists are sorted, so one merge finds the repeats. The work counters
// therefore come out as the textbook walk's: cells, tests and mailbox repeats alike.
#pragma once

#include "fast/grid_cell_sort.h"
#include "framework/accel/accelerator.h"
#include "framework/interface/grid.h"

namespace rtlab {

class FastGridAccelerator final : public Accelerator {
public:
    explicit FastGridAccelerator(const GridOptions& options) : options_(options) {}

    void build(const PrimitiveSet& primitives) override;
    Hit intersect(const Ray& ray, TraversalStats& stats) const override;
    bool occluded(const Ray& ray, TraversalStats& stats) const override;
    // As the textbook grid's: a root whose children are the cells, in cellIndex order.
    StructureView structure() const override;
    size_t memoryBytes() const override {
        return (cells_.cellStart.size() + cells_.primIndices.size()) * sizeof(uint32_t);
    }

private:
    // The walk shared by both queries; Query decides what a cell's new primitives do and when
    // the walk ends (fast_grid_accelerator.cpp).
    template <typename Query>
    void walk(const Ray& ray, float tMax, TraversalStats& stats, Query& query) const;

    GridOptions options_;
    const PrimitiveSet* primitives_ = nullptr;
    UniformGrid frame_;  // bounds, resolution and widths; its own cell lists stay empty
    GridCells cells_;
};

}  // namespace rtlab
