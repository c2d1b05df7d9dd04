// The wide BVH as an accelerator: a W-wide tree (wide_bvh.h) traversed with a W-wide slab test
// and the watertight triangle test on four triangles at once (triangle_packet.h). The tree
// comes from one of two builders:
//  * the student's (or the reference) binary tree of a1/a2, folded W-wide (--accel bvh4-sah,
//    bvh8-buckets:12, ...; wide_bvh_layouts.cpp): what the same tree gains from layout and SIMD
//    alone;
//  * fast/'s own builder (--accel fastbvh; wide_bvh_builder.h, fast_bvh.cpp), which prices
//    leaves by the packets they fill and builds on every thread.
//
// These are the fast paths the benchmarks put next to Embree; the student's own traversal is the
// binary one (BvhAccelerator). The SIMD code is written with GCC's vector extensions, so it
// compiles for any target: W = 4 fills an SSE or NEON register, W = 8 an AVX register (with
// -mavx or -march=native; without, the compiler splits it into two 4-wide halves).
#pragma once

#include "fast/task_pool.h"
#include "fast/triangle_packet.h"
#include "fast/wide_bvh.h"
#include "fast/wide_bvh_dispatch.h"
#include "framework/accel/accelerator.h"

#include <functional>

namespace rtlab {

template <int W>
class WideBvhAccelerator final : public Accelerator {
public:
    // Makes the wide tree over a primitive set (never called for an empty one).
    using TreeBuilder = std::function<WideBvh<W>(const PrimitiveSet&)>;

    // packingThreads: how many threads copy the triangles into the leaves' packets (0: every CPU
    // the process may use).
    WideBvhAccelerator(TreeBuilder makeTree, int packingThreads)
        : makeTree_(std::move(makeTree)), packingThreads_(packingThreads > 0 ? packingThreads : availableCpus()) {}

    void build(const PrimitiveSet& primitives) override;
    // Node visits count wide nodes (W box tests each).
    Hit intersect(const Ray& ray, TraversalStats& stats) const override;
    bool occluded(const Ray& ray, TraversalStats& stats) const override;
    // The scene seen from point (point_view.h), or nullptr where it cannot help.
    std::unique_ptr<PointQueries> queriesAt(const Vec3& point) const override;
    StructureView structure() const override;
    size_t memoryBytes() const override;

private:
    TreeBuilder makeTree_;
    int packingThreads_;
    const PrimitiveSet* primitives_ = nullptr;
    bool hasSpheres_ = false;
    // The wide tree, each node followed by its leaves' packets (WideBvhArrays); a leaf's
    // primCount primitives fill its first packet and the next ones, four to a packet.
    HugePageVector<TreeUnit> memory_;
    WideBvhArrays<W> arrays_;       // memory_, for the traversal
    WideTraversal<W> traversal_{};  // the copy this CPU runs (wide_bvh_dispatch.h)
};

}  // namespace rtlab
