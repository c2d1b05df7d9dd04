// Wraps the octree of assignment a4 in the Accelerator interface through its adapter
// (octree_adapter.h): building runs the student's buildOctree over the primitive set, queries
// the student's traversal.
#pragma once

#include "framework/accel/accelerator.h"
#include "framework/accel/accelerator_registry.h"
#include "framework/interface/octree.h"

#include <span>

namespace rtlab {

// An octree as the grader's StructureView: the nodes with their boxes (childBox of the
// parent's), children in index order. Children must come after their parent, as buildOctree
// lays them out.
StructureView octreeStructureView(const Octree& octree);
// The same with each node's box given (nodeBoxes[i] for node i; a node past the list gets an
// empty box): octree_structure_view.cpp, which calls no assignment code, so the grader can
// draw an octree a worker sent with its own boxes. Every interior node's children must exist.
StructureView octreeStructureView(const Octree& octree, std::span<const Bounds3f> nodeBoxes);

class OctreeAccelerator final : public Accelerator {
public:
    explicit OctreeAccelerator(const OctreeOptions& options) : options_(options) {}
    // Reads the registry's octree options (maxPrims, maxDepth, insert).
    static std::unique_ptr<Accelerator> create(const AcceleratorParameters& parameters);

    void build(const PrimitiveSet& primitives) override;
    Hit intersect(const Ray& ray, TraversalStats& stats) const override;
    bool occluded(const Ray& ray, TraversalStats& stats) const override;
    // The nodes with their boxes (childBox of the parent's), children in index order.
    StructureView structure() const override;
    size_t memoryBytes() const override {
        return octree_.nodes.size() * sizeof(OctreeNode) + octree_.primIndices.size() * sizeof(uint32_t);
    }

    const Octree& octree() const { return octree_; }

private:
    OctreeOptions options_;
    const PrimitiveSet* primitives_ = nullptr;
    Octree octree_;
};

}  // namespace rtlab
