// The simplest accelerator: test every primitive. The first implementation of the interface
// and the baseline every structure is measured against.
#pragma once

#include "framework/accel/accelerator.h"

namespace rtlab {

class BruteForce final : public Accelerator {
public:
    void build(const PrimitiveSet& primitives) override { primitives_ = &primitives; }
    Hit intersect(const Ray& ray, TraversalStats& stats) const override;
    bool occluded(const Ray& ray, TraversalStats& stats) const override;
    StructureView structure() const override;
    size_t memoryBytes() const override { return 0; }

private:
    const PrimitiveSet* primitives_ = nullptr;
};

}  // namespace rtlab
