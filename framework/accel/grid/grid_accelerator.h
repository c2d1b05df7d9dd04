// Wraps the uniform grid of assignment a3 in the Accelerator interface through its adapter
// (grid_adapter.h): building runs the framework's gridFrame and the student's fillGridCells
// (then, with exact insertion, a4's triangle-box test on every cell), queries the student's
// traversal.
#pragma once

#include "framework/accel/accelerator.h"
#include "framework/accel/accelerator_registry.h"
#include "framework/accel/grid/grid_adapter.h"
#include "framework/interface/grid.h"

namespace rtlab {

class GridAccelerator final : public Accelerator {
public:
    GridAccelerator(const GridOptions& options, GridInsertion insertion) : options_(options), insertion_(insertion) {}
    // Reads the registry's grid options (C, res, insert).
    static std::unique_ptr<Accelerator> create(const AcceleratorParameters& parameters);

    void build(const PrimitiveSet& primitives) override;
    Hit intersect(const Ray& ray, TraversalStats& stats) const override;
    bool occluded(const Ray& ray, TraversalStats& stats) const override;
    // The grid as a root whose children are its cells, in cellIndex order.
    StructureView structure() const override;
    size_t memoryBytes() const override {
        return (grid_.cellStart.size() + grid_.primIndices.size()) * sizeof(uint32_t);
    }

    const UniformGrid& grid() const { return grid_; }

private:
    GridOptions options_;
    GridInsertion insertion_;
    const PrimitiveSet* primitives_ = nullptr;
    UniformGrid grid_;
};

}  // namespace rtlab
