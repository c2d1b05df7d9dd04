// Wraps the KD-tree of assignment a5 in the Accelerator interface through its adapter
// (kdtree_adapter.h): building runs the student's buildKdTree (build=sort) or buildKdTreeNlogN
// (build=nlogn), queries the student's traversal.
#pragma once

#include "framework/accel/accelerator.h"
#include "framework/accel/accelerator_registry.h"
#include "framework/accel/kdtree/kdtree_adapter.h"
#include "framework/interface/kdtree.h"

namespace rtlab {

// A KD-tree as the grader's StructureView: every node with its box (the root's box cut by the
// planes above it), depth first, below child first, and each interior node's plane. The tree
// must be well formed (as a builder made it: children inside the array, no cycles). In
// kdtree_structure_view.cpp, which calls no assignment code (rtlab-grader links it).
StructureView kdTreeStructureView(const KdTree& tree);

class KdTreeAccelerator final : public Accelerator {
public:
    KdTreeAccelerator(const KdTreeOptions& options, KdBuilder builder) : options_(options), builder_(builder) {}
    // Reads the registry's KD-tree options (build, KT, KI, eb, leaf, depth).
    static std::unique_ptr<Accelerator> create(const AcceleratorParameters& parameters);

    void build(const PrimitiveSet& primitives) override;
    Hit intersect(const Ray& ray, TraversalStats& stats) const override;
    bool occluded(const Ray& ray, TraversalStats& stats) const override;
    // Every node with its box (the root's box cut by the planes above it), below child first,
    // and each interior node's plane.
    StructureView structure() const override;
    size_t memoryBytes() const override { return tree_.nodes.size() * sizeof(KdNode) + tree_.primIndices.size() * sizeof(uint32_t); }

    const KdTree& tree() const { return tree_; }

private:
    KdTreeOptions options_;
    KdBuilder builder_;
    const PrimitiveSet* primitives_ = nullptr;
    KdTree tree_;
};

}  // namespace rtlab
