// Reference solution: bucketed SAH, the lecture's pseudocode (docs/a2-sah.md#buckets).
#include "sah_cost.h"

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
    // Scratch reused across nodes, so the build does not allocate per node: the bins, the
    // non-empty buckets and the right sides of their planes, each primitive's bucket per axis,
    // and room for the partition. Only the B bins in use are cleared: most nodes hold a handful
    // of primitives, and clearing all kMaxBuckets used to cost more than binning them.
    thread_local std::vector<Bucket> bins;
    thread_local std::vector<Bucket> buckets, right;
    thread_local std::array<std::vector<uint8_t>, 3> bucketIds;
    thread_local std::vector<BuildPrimitive> rightPart;
    if (buckets.size() < static_cast<size_t>(B)) {
        buckets.resize(B);
        right.resize(B);
    }

    double bestArea = std::numeric_limits<double>::infinity();
    int bestAxis = -1, bestPlane = 0;  // plane p: buckets 0..p left, p+1..B-1 right
    Vec3 centroidExtent = node.centroidBounds.diagonal();
    int longest = node.centroidBounds.longestAxis();
    for (int axis = 0; axis < 3; ++axis) {
        if (options.allAxes ? !(centroidExtent[axis] > 0) : axis != longest) continue;
        BucketIndex bucketOf{B, node.centroidBounds.lower[axis], centroidExtent[axis]};
        if (bucketIds[axis].size() < n) bucketIds[axis].resize(n);
        bins.assign(B, Bucket{});
        // Plain pointers for the hot loop: a store through a uint8_t may alias anything, so
        // through the vectors the compiler would reload their data pointers after every id.
        uint8_t* ids = bucketIds[axis].data();
        Bucket* bin = bins.data();
        for (uint32_t i = 0; i < n; ++i) {
            int id = bucketOf(prims[i].centroid[axis]);
            ids[i] = static_cast<uint8_t>(id);
            ++bin[id].count;
            bin[id].bounds.extend(prims[i].bounds);
        }
        // Only a plane right behind a non-empty bucket can win: behind an empty one the split is
        // the same as one plane lower, and ties go to the lower plane. So the sweeps run over
        // the non-empty buckets only (most nodes are small and fill few of them).
        int used = 0;
        std::array<int, kMaxBuckets> planeAfter;  // the plane right behind each of them
        for (int b = 0; b < B; ++b) {
            if (bin[b].count == 0) continue;
            buckets[used] = bin[b];
            planeAfter[used++] = b;
        }
        // Sweep from the right for the right sides, then from the left evaluating each plane
        // (j: non-empty buckets 0..j left, j+1..used-1 right; neither side is empty).
        Bucket suffix;
        for (int j = used - 1; j >= 1; --j) {
            suffix = {suffix.count + buckets[j].count, unionOf(suffix.bounds, buckets[j].bounds)};
            right[j] = suffix;
        }
        Bucket left;
        for (int j = 0; j + 1 < used; ++j) {
            left = {left.count + buckets[j].count, unionOf(left.bounds, buckets[j].bounds)};
            double area = weightedChildArea(left.bounds, left.count, right[j + 1].bounds, right[j + 1].count);
            if (area < bestArea) {  // strict: ties keep the lower axis, then the lower plane
                bestArea = area;
                bestAxis = axis;
                bestPlane = planeAfter[j];
            }
        }
    }
    if (bestAxis < 0 || !splitBeatsLeaf(bestArea, n, node, options)) return 0;

    // Partition by the stored bucket ids. Left primitives move forward within the range, keeping
    // their order (the slot a primitive moves to has been read already); right ones wait in the
    // scratch and are written behind them in reverse order, the order this solution has always
    // produced (grader/reference pins the trees). So only the right part is copied twice.
    if (rightPart.size() < n) rightPart.resize(n);
    const uint8_t* ids = bucketIds[bestAxis].data();
    BuildPrimitive* waiting = rightPart.data();
    uint32_t front = 0, rightCount = 0;
    while (ids[front] <= bestPlane) ++front;  // leading left ones stay put (a right one follows)
    for (uint32_t i = front; i < n; ++i) {
        if (ids[i] <= bestPlane)
            prims[front++] = prims[i];
        else
            waiting[rightCount++] = prims[i];
    }
    std::reverse_copy(waiting, waiting + rightCount, prims.begin() + front);
    return front;
}

}  // namespace rtlab
