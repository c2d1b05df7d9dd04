// The wide BVH as an accelerator (--accel bvh4-sah, bvh8-buckets:12, ...): builds the binary
// BVH with assignment a1/a2's buildBvh, folds it W-wide (wide_bvh.h) and traverses it with a
// W-wide slab test and the watertight triangle test on four triangles at once (triangle_packet.h).
//
// This is the fast path the benchmarks put next to Embree (registered as a BVH layout by
// wide_bvh_layouts.cpp). It shows what the same tree gains from layout and SIMD alone; the
// student's own traversal is the binary one (BvhAccelerator). The SIMD code is written with GCC's vector extensions, so it compiles
// for any target: W = 4 fills an SSE or NEON register, W = 8 an AVX register (with -mavx or
// -march=native; without, the compiler splits it into two 4-wide halves).
#pragma once

#include "fast/triangle_packet.h"
#include "fast/wide_bvh.h"
#include "framework/accel/accelerator.h"

namespace rtlab {

template <int W>
class WideBvhAccelerator final : public Accelerator {
public:
    explicit WideBvhAccelerator(const BvhOptions& options) : options_(options) {}

    void build(const PrimitiveSet& primitives) override;
    // Node visits count wide nodes (W box tests each).
    Hit intersect(const Ray& ray, TraversalStats& stats) const override;
    bool occluded(const Ray& ray, TraversalStats& stats) const override;
    StructureView structure() const override;
    size_t memoryBytes() const override;

private:
    // The traversals, compiled twice: with kSpheres false (the scene is all triangles) the
    // loop makes no calls, so its SIMD registers need not be saved around them.
    template <bool kSpheres>
    Hit closestHit(const Ray& ray, TraversalStats& stats) const;
    template <bool kSpheres>
    bool anyHit(const Ray& ray, TraversalStats& stats) const;
    // Tests the spheres among a packet's primitives (lanes without a triangle), updating hit;
    // true when one is hit.
    bool intersectSpheres(const TrianglePacket& packet, const Ray& ray, Hit& hit) const;

    BvhOptions options_;
    const PrimitiveSet* primitives_ = nullptr;
    bool hasSpheres_ = false;
    // The wide tree; a leaf child refers to its first packet (kLeafFlag | packet index), and
    // its primCount primitives fill that packet and the next ones, four to a packet.
    std::vector<WideBvhNode<W>, HugePageAllocator<WideBvhNode<W>>> nodes_;
    std::vector<TrianglePacket, HugePageAllocator<TrianglePacket>> packets_;
};

}  // namespace rtlab
