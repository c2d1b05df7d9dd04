// The framework's part of BVH building: the rules shared by every split heuristic, and the
// dispatch to the heuristic the options name.
#include "framework/core/error.h"
#include "framework/interface/a1_bvh.h"
#include "framework/interface/a2_sah.h"

#include <cstddef>
#include <string>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace rtlab {

NodeInfo describeNode(std::span<const BuildPrimitive> prims) {
    NodeInfo node;
#if defined(__SSE2__)
    // Every level of a build runs this over all primitives. Compiled for baseline x86-64 (no
    // AVX), the loop below costs three instructions per coordinate; four-wide min/max does the
    // same in a quarter of them. _mm_min_ps(p, acc) is (p < acc) ? p : acc, which is exactly
    // glm::min(acc, p) as Bounds3f::extend computes it, NaN and signed zeros included, so the
    // result is bit for bit that of the loop. Each load takes the 16 bytes at a Vec3: its three
    // floats and 4 bytes of the next member (dropped: only lanes 0-2 are kept).
    static_assert(offsetof(BuildPrimitive, centroid) + 4 * sizeof(float) <= sizeof(BuildPrimitive));
    auto load = [](const Vec3& v) { return _mm_loadu_ps(&v.x); };
    __m128 lower = _mm_set1_ps(kInfinity), upper = _mm_set1_ps(-kInfinity);
    __m128 centroidLower = lower, centroidUpper = upper;
    for (const BuildPrimitive& p : prims) {
        __m128 centroid = load(p.centroid);
        lower = _mm_min_ps(load(p.bounds.lower), lower);
        upper = _mm_max_ps(load(p.bounds.upper), upper);
        centroidLower = _mm_min_ps(centroid, centroidLower);
        centroidUpper = _mm_max_ps(centroid, centroidUpper);
    }
    auto toVec3 = [](__m128 v) {
        alignas(16) float f[4];
        _mm_store_ps(f, v);
        return Vec3(f[0], f[1], f[2]);
    };
    node.bounds.lower = toVec3(lower);
    node.bounds.upper = toVec3(upper);
    node.centroidBounds.lower = toVec3(centroidLower);
    node.centroidBounds.upper = toVec3(centroidUpper);
#else
    for (const BuildPrimitive& p : prims) {
        node.bounds.extend(p.bounds);
        node.centroidBounds.extend(p.centroid);
    }
#endif
    return node;
}

static bool isSah(SplitMethod method) {
    return method == SplitMethod::SahSweep || method == SplitMethod::SahBuckets;
}

uint32_t splitNode(std::span<BuildPrimitive> prims, const NodeInfo& node, int depth,
                   const BvhOptions& options) {
    const auto n = static_cast<uint32_t>(prims.size());
    bool zeroCentroidExtent = node.centroidBounds.lower == node.centroidBounds.upper;
    if (n <= 1 || zeroCentroidExtent || depth >= kMaxBvhDepth - 1) return 0;
    if (!isSah(options.method) && n <= static_cast<uint32_t>(options.maxLeaf)) return 0;

    uint32_t left = 0;
    switch (options.method) {
    case SplitMethod::Median: left = splitMedian(prims, node); break;
    case SplitMethod::Middle: left = splitMiddle(prims, node); break;
    case SplitMethod::EqualCounts: left = splitEqualCounts(prims, node); break;
    case SplitMethod::SahSweep: left = splitSahSweep(prims, node, options); break;
    case SplitMethod::SahBuckets: left = splitSahBuckets(prims, node, options); break;
    }
    // A split that leaves one side empty would recurse forever; say so instead.
    if (left >= n || (left == 0 && !isSah(options.method)))
        throw Error("split function returned " + std::to_string(left) + " of " + std::to_string(n) +
                    " primitives for the left child (must be between 1 and n-1)");
    return left;
}

}  // namespace rtlab
