// Reference solution: bucketed SAH, the lecture's pseudocode (docs/a2-sah.md#buckets).
#include "solutions/a2_sah/sah_cost.h"

#include <algorithm>
#include <array>
#include <limits>
#include <vector>

namespace rtlab {
namespace {

constexpr int kMaxBuckets = 32;

struct Bucket {
    uint32_t count = 0;
    Bounds3f bounds;
};

// The pinned bucket formula, min(B-1, floor(B (c - cmin) / (cmax - cmin))), evaluated in float
// in exactly this order. Used for binning and for partitioning, so the evaluated split and the
// executed one agree. A NaN centroid lands in the last bucket instead of an undefined index.
struct BucketIndex {
    int buckets;
    float cmin, extent;

    int operator()(float c) const {
        float f = buckets * (c - cmin) / extent;
        return f < buckets ? (f > 0 ? static_cast<int>(f) : 0) : buckets - 1;
    }
};

}  // namespace

uint32_t splitSahBuckets(std::span<BuildPrimitive> prims, const NodeInfo& node, const BvhOptions& options) {
    const auto n = static_cast<uint32_t>(prims.size());
    const int B = options.buckets;
    // Scratch reused across nodes (no allocation per node): each primitive's bucket per axis,
    // and room for the partition.
    thread_local std::array<std::vector<uint8_t>, 3> bucketIds;
    thread_local std::vector<BuildPrimitive> partitioned;

    double bestArea = std::numeric_limits<double>::infinity();
    int bestAxis = -1, bestPlane = 0;  // plane p: buckets 0..p left, p+1..B-1 right
    Vec3 centroidExtent = node.centroidBounds.diagonal();
    int longest = node.centroidBounds.longestAxis();
    for (int axis = 0; axis < 3; ++axis) {
        if (options.allAxes ? !(centroidExtent[axis] > 0) : axis != longest) continue;
        BucketIndex bucketOf{B, node.centroidBounds.lower[axis], centroidExtent[axis]};
        std::vector<uint8_t>& ids = bucketIds[axis];
        if (ids.size() < n) ids.resize(n);
        std::array<Bucket, kMaxBuckets> buckets{};
        for (uint32_t i = 0; i < n; ++i) {
            int id = bucketOf(prims[i].centroid[axis]);
            ids[i] = static_cast<uint8_t>(id);
            ++buckets[id].count;
            buckets[id].bounds.extend(prims[i].bounds);
        }
        // Sweep from the right for the right sides, then from the left evaluating each plane.
        std::array<Bucket, kMaxBuckets> right;
        right[B - 1] = buckets[B - 1];
        for (int i = B - 2; i >= 1; --i)
            right[i] = {right[i + 1].count + buckets[i].count, unionOf(right[i + 1].bounds, buckets[i].bounds)};
        Bucket left;
        for (int plane = 0; plane < B - 1; ++plane) {
            left = {left.count + buckets[plane].count, unionOf(left.bounds, buckets[plane].bounds)};
            const Bucket& r = right[plane + 1];
            if (left.count == 0 || r.count == 0) continue;  // no empty child
            double area = weightedChildArea(left.bounds, left.count, r.bounds, r.count);
            if (area < bestArea) {  // strict: ties keep the lower axis, then the lower plane
                bestArea = area;
                bestAxis = axis;
                bestPlane = plane;
            }
        }
    }
    if (bestAxis < 0 || !splitBeatsLeaf(bestArea, n, node, options)) return 0;

    // Partition by the stored bucket ids: left ones fill the scratch from the front, right ones
    // from the back, without a branch to mispredict.
    const std::vector<uint8_t>& ids = bucketIds[bestAxis];
    if (partitioned.size() < n) partitioned.resize(n);
    uint32_t front = 0, back = n - 1;
    for (uint32_t i = 0; i < n; ++i) {
        bool isLeft = ids[i] <= bestPlane;
        partitioned[isLeft ? front : back] = prims[i];
        front += isLeft;
        back -= !isLeft;
    }
    std::copy(partitioned.begin(), partitioned.begin() + n, prims.begin());
    return front;
}

}  // namespace rtlab
