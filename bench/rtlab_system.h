// One of rtlab's accelerators (the implementation this executable links: the reference
// solutions for rtlab-solution-bench, the student's code for rtlab-bench), driven through the
// framework's Accelerator interface exactly as the renderer drives it.
#pragma once

#include "bench/bench_system.h"
#include "framework/accel/accelerator.h"
#include "framework/accel/primitive_set.h"

#include <memory>

namespace rtlab::bench {

class RtlabSystem final : public BenchSystem {
public:
    RtlabSystem(const PrimitiveSet& primitives, const AcceleratorSpec& spec);

    std::string label() const override;
    double build(int threads) override;
    void trace(std::span<const BenchRay> rays, TraceResult* results, TraversalStats& stats) const override;
    void occluded(std::span<const BenchSegment> rays, uint8_t* blocked, TraversalStats& stats) const override;
    bool buildsInParallel() const override;
    bool countsWork() const override { return true; }
    std::optional<double> sahCost() const override;
    double bytesPerTriangle() const override;
    std::optional<double> referencesPerTriangle() const override;

    const Accelerator& accelerator() const { return *accelerator_; }

private:
    const PrimitiveSet& primitives_;
    AcceleratorSpec spec_;
    std::unique_ptr<Accelerator> accelerator_;
};

// The accelerator `name` with the bench's --max-leaf, which sets the BVH's leaf as render's flag
// does: only away from its default 4.
AcceleratorSpec withMaxLeaf(const std::string& name, int maxLeaf);

// "rtlab:" + the --accel name, with ":L<maxLeaf>" when --max-leaf set the leaf.
std::string rtlabLabel(const AcceleratorSpec& spec);

}  // namespace rtlab::bench
