// Wraps the two-level grid (a3, beyond the lecture) in the Accelerator interface.
#pragma once

#include "framework/accel/accelerator.h"
#include "framework/accel/accelerator_registry.h"
#include "framework/interface/grid.h"

namespace rtlab {

class TwoLevelGridAccelerator final : public Accelerator {
public:
    TwoLevelGridAccelerator(const GridOptions& top, const GridOptions& child, uint32_t refineAbove)
        : top_(top), child_(child), refineAbove_(refineAbove) {}
    // Reads the registry's two-level grid options (top, C, res, refine).
    static std::unique_ptr<Accelerator> create(const AcceleratorParameters& parameters);

    void build(const PrimitiveSet& primitives) override;
    Hit intersect(const Ray& ray, TraversalStats& stats) const override;
    bool occluded(const Ray& ray, TraversalStats& stats) const override;
    // The top grid's cells, each with its child grid's cells below it.
    StructureView structure() const override;
    size_t memoryBytes() const override;

private:
    GridOptions top_, child_;
    uint32_t refineAbove_;
    const PrimitiveSet* primitives_ = nullptr;
    TwoLevelGrid grid_;
};

}  // namespace rtlab
