// Wraps the BVH of assignments a1/a2 in the Accelerator interface through its adapter
// (bvh_adapter.h): building runs buildBvh with the chosen split method, queries run the ordered
// (or, on request, the recursive) traversal.
#pragma once

#include "framework/accel/accelerator.h"
#include "framework/accel/accelerator_registry.h"
#include "framework/accel/bvh_adapter.h"
#include "framework/interface/bvh.h"

namespace rtlab {

// A BVH as the grader's StructureView: its nodes in order, children {first, second}. This and
// drawBvh live in bvh_structure_view.cpp, which calls no assignment code (rtlab-grader links them).
StructureView bvhStructureView(const Bvh& bvh);
// How the viewer draws a binary BVH: boxes by level, each node's SAH share (structure_drawing.h).
StructureDrawing drawBvh(const StructureView& view, const NodeMask& drawn);

// The tree options of a bvh, bvh4 or bvh8 name (split, B, leaf, axes).
BvhOptions bvhOptionsFrom(const AcceleratorParameters& parameters);

// The BVH's flags as the command line sets them (--max-leaf, --traversal, --sah-axes): each only
// away from its default, so a flag left at its default may be given for a structure without the
// option, and a value in the name (bvh-sah,leaf=8) stands.
void setMaxLeaf(AcceleratorSpec& spec, int maxLeaf);
void setTraversal(AcceleratorSpec& spec, const std::string& order);  // "ordered" or "recursive"
void setSahAxes(AcceleratorSpec& spec, const std::string& axes);     // "longest" or "all"

class BvhAccelerator final : public Accelerator {
public:
    BvhAccelerator(const BvhOptions& options, bool recursiveTraversal)
        : options_(options), recursiveTraversal_(recursiveTraversal) {}
    // Reads the registry's BVH options (split, B, leaf, axes, traversal).
    static std::unique_ptr<Accelerator> create(const AcceleratorParameters& parameters);

    void build(const PrimitiveSet& primitives) override;
    Hit intersect(const Ray& ray, TraversalStats& stats) const override;
    bool occluded(const Ray& ray, TraversalStats& stats) const override;
    StructureView structure() const override;
    size_t memoryBytes() const override {
        return bvh_.nodes.size() * sizeof(BvhNode) + bvh_.primIndices.size() * sizeof(uint32_t);
    }

    const Bvh& bvh() const { return bvh_; }

private:
    BvhOptions options_;
    bool recursiveTraversal_;
    const PrimitiveSet* primitives_ = nullptr;
    Bvh bvh_;
};

}  // namespace rtlab
