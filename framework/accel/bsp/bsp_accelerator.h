// Wraps a5's optional BSP autopartition in the Accelerator interface through its adapter
// (bsp_adapter.h; docs/bsp.md).
#pragma once

#include "framework/accel/accelerator.h"
#include "framework/accel/accelerator_registry.h"
#include "framework/interface/bsp.h"

namespace rtlab {

// A BSP tree as the grader's StructureView: every node with the tree's box, its children
// {back, front} and its plane; interior nodes keep the primitives lying in their plane.
StructureView bspStructureView(const BspTree& tree);

class BspAccelerator final : public Accelerator {
public:
    explicit BspAccelerator(const BspOptions& options) : options_(options) {}
    // Reads the registry's BSP options (leaf, depth).
    static std::unique_ptr<Accelerator> create(const AcceleratorParameters& parameters);

    void build(const PrimitiveSet& primitives) override;
    Hit intersect(const Ray& ray, TraversalStats& stats) const override;
    bool occluded(const Ray& ray, TraversalStats& stats) const override;
    // The nodes without boxes (a BSP cell is a convex polytope): each with the tree's box, its
    // children {back, front} and its plane. Interior nodes keep the primitives lying in their plane.
    StructureView structure() const override;
    size_t memoryBytes() const override { return tree_.nodes.size() * sizeof(BspNode) + tree_.primIndices.size() * sizeof(uint32_t); }

private:
    BspOptions options_;
    const PrimitiveSet* primitives_ = nullptr;
    BspTree tree_;
};

}  // namespace rtlab
