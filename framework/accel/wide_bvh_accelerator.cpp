#include "framework/accel/wide_bvh_accelerator.h"

#include "framework/accel/bvh_accelerator.h"
#include "framework/core/float_bits.h"
#include "framework/interface/a1_bvh.h"

#include <bit>
#include <cstring>

namespace rtlab {
namespace {

// W floats in one SIMD register (GCC vector extension): +, -, *, comparisons and ?: work lane
// by lane.
template <int W>
struct SimdTypes {
    typedef float Lanes __attribute__((vector_size(W * sizeof(float))));
    typedef int32_t LaneMask __attribute__((vector_size(W * sizeof(int32_t))));  // -1 or 0 per lane
};

template <int W>
using Lanes = typename SimdTypes<W>::Lanes;

template <int W>
Lanes<W> broadcast(float value) {
    return value - Lanes<W>{};
}

template <int W>
Lanes<W> loadRow(const float (&row)[W]) {
    Lanes<W> lanes;
    std::memcpy(&lanes, row, sizeof lanes);
    return lanes;
}

// What the W-wide slab test needs per ray, each value broadcast to all lanes.
template <int W>
struct WideRay {
    Lanes<W> origin[3];
    Lanes<W> invDirection[3];
    Lanes<W> tMin;
    // Per axis, the plane row the ray enters a box through and the one it leaves through:
    // lower then upper for a positive direction, the other way round for a negative one.
    int nearRow[3], farRow[3];

    explicit WideRay(const Ray& ray) : tMin(broadcast<W>(ray.tMin)) {
        RayInverse inverse(ray);
        for (int axis = 0; axis < 3; ++axis) {
            origin[axis] = broadcast<W>(inverse.origin[axis]);
            invDirection[axis] = broadcast<W>(inverse.invDirection[axis]);
            bool negative = inverse.dirIsNegative[axis];
            nearRow[axis] = negative ? WideBvhNode<W>::upperRow(axis) : WideBvhNode<W>::lowerRow(axis);
            farRow[axis] = negative ? WideBvhNode<W>::lowerRow(axis) : WideBvhNode<W>::upperRow(axis);
        }
    }
};

// The slab test of a0 on W boxes at once: per child, where the ray enters its box and whether
// the segment (tMin, tMax] touches it. Same arithmetic as the scalar test, including the
// enlarged far distance.
template <int W>
struct ChildHits {
    Lanes<W> tEnter;
    typename SimdTypes<W>::LaneMask hit;
};

template <int W>
ChildHits<W> intersectChildren(const WideBvhNode<W>& node, const WideRay<W>& ray, float tMax) {
    const Lanes<W> farScale = broadcast<W>(1.0f + 2.0f * gamma(3));
    Lanes<W> tNear = ray.tMin, tFar = broadcast<W>(tMax);
    for (int axis = 0; axis < 3; ++axis) {
        Lanes<W> t0 = (loadRow<W>(node.planes[ray.nearRow[axis]]) - ray.origin[axis]) * ray.invDirection[axis];
        Lanes<W> t1 = (loadRow<W>(node.planes[ray.farRow[axis]]) - ray.origin[axis]) * ray.invDirection[axis];
        t1 *= farScale;
        // A NaN distance (0 * inf: the origin on a slab plane, direction 0 on that axis) fails
        // the comparison and leaves the interval as it was. This is max and min (MAXPS/MINPS).
        tNear = t0 > tNear ? t0 : tNear;
        tFar = t1 < tFar ? t1 : tFar;
    }
    return {tNear, tNear <= tFar};
}

// A child waiting to be visited.
struct StackEntry {
    uint32_t ref;  // interior node index, or kLeafFlag | first primIndices entry
    uint32_t primCount;
    float tEnter;
};

// Every wide node on the current path leaves at most W - 1 siblings on the stack, and a wide
// tree is no deeper than its binary tree; the last node's W children are written in place.
template <int W>
constexpr int kStackSize = (W - 1) * kMaxBvhDepth + W;

// Writes the children the ray hits to out, farthest first, so the nearest is out[count - 1];
// returns count. Every child is written and the count advances only past hit ones, so the
// compaction has no branch to mispredict; then an insertion sort (one or two children are
// hit at most nodes).
template <int W>
inline int orderChildren(const WideBvhNode<W>& node, const ChildHits<W>& hits, StackEntry* out) {
    float tEnter[W];
    int32_t hit[W];
    std::memcpy(tEnter, &hits.tEnter, sizeof tEnter);  // two stores instead of a shuffle per lane
    std::memcpy(hit, &hits.hit, sizeof hit);
    unsigned mask = 0;
    for (int slot = 0; slot < W; ++slot) mask |= (hit[slot] & 1u) << slot;
    int count = 0;
    for (; mask != 0; mask &= mask - 1) {
        int slot = std::countr_zero(mask);
        out[count++] = {node.child[slot], node.primCount[slot], tEnter[slot]};
    }
    for (int i = 1; i < count; ++i)
        for (int j = i; j > 0 && out[j - 1].tEnter < out[j].tEnter; --j) std::swap(out[j - 1], out[j]);
    return count;
}

}  // namespace

template <int W>
void WideBvhAccelerator<W>::build(const PrimitiveSet& primitives) {
    primitives_ = &primitives;
    std::vector<BuildPrimitive> prims = buildPrimitivesOf(primitives);
    bvh_ = prims.empty() ? WideBvh<W>{} : collapseToWide<W>(buildBvh(std::move(prims), options_));

    leafTriangles_.resize(bvh_.primIndices.size());
    for (size_t i = 0; i < bvh_.primIndices.size(); ++i)
        if (bvh_.primIndices[i] < primitives.triangleCount())
            leafTriangles_[i] = coordinatesOf(primitives.triangle(bvh_.primIndices[i]));
}

template <int W>
Hit WideBvhAccelerator<W>::intersect(const Ray& ray, TraversalStats& stats) const {
    ++stats.rays;
    Hit hit;
    hit.t = ray.tMax;
    if (bvh_.nodes.empty()) return Hit{};

    const WideRay<W> wideRay(ray);
    const ShearedRay shearedRay(ray);
    const uint32_t triangleCount = primitives_->triangleCount();
    uint64_t nodeVisits = 0, primitiveTests = 0;
    StackEntry stack[kStackSize<W>];
    int stackSize = 0;
    StackEntry current{0, 0, ray.tMin};
    for (;;) {
        if (!(current.ref & kLeafFlag)) {
            const WideBvhNode<W>& node = bvh_.nodes[current.ref];
            ++nodeVisits;
            // The hit children go onto the stack, the nearest on top; it is visited next, the
            // others wait, farthest deepest.
            StackEntry* pushed = stack + stackSize;
            int count = orderChildren<W>(node, intersectChildren<W>(node, wideRay, hit.t), pushed);
            if (count > 0) {
                stackSize += count - 1;
                current = pushed[count - 1];
                continue;
            }
        } else {
            uint32_t first = current.ref & ~kLeafFlag;
            primitiveTests += current.primCount;
            for (uint32_t i = first; i < first + current.primCount; ++i) {
                uint32_t prim = bvh_.primIndices[i];
                TriangleHit triangleHit;
                if (prim >= triangleCount)
                    primitives_->intersect(prim, ray, hit);
                else if (shearedRay.intersect(leafTriangles_[i], hit.t, &triangleHit))
                    hit = Hit{triangleHit.t, prim, triangleHit.b1, triangleHit.b2};
            }
        }
        // Next waiting child, skipping those that start beyond the closest hit so far.
        do {
            if (stackSize == 0) {
                stats.nodeVisits += nodeVisits;
                stats.primitiveTests += primitiveTests;
                if (!hit.found()) hit.t = kInfinity;
                return hit;
            }
            current = stack[--stackSize];
        } while (current.tEnter > hit.t);
    }
}

template <int W>
bool WideBvhAccelerator<W>::occluded(const Ray& ray, TraversalStats& stats) const {
    ++stats.rays;
    if (bvh_.nodes.empty()) return false;

    const WideRay<W> wideRay(ray);
    const ShearedRay shearedRay(ray);
    const uint32_t triangleCount = primitives_->triangleCount();
    StackEntry stack[kStackSize<W>];
    int stackSize = 0;
    stack[stackSize++] = StackEntry{0, 0, ray.tMin};
    while (stackSize > 0) {
        StackEntry current = stack[--stackSize];
        if (!(current.ref & kLeafFlag)) {
            const WideBvhNode<W>& node = bvh_.nodes[current.ref];
            ++stats.nodeVisits;
            stackSize += orderChildren<W>(node, intersectChildren<W>(node, wideRay, ray.tMax), stack + stackSize);
            continue;
        }
        uint32_t first = current.ref & ~kLeafFlag;
        for (uint32_t i = first; i < first + current.primCount; ++i) {
            ++stats.primitiveTests;
            uint32_t prim = bvh_.primIndices[i];
            Hit hit;
            hit.t = ray.tMax;
            TriangleHit triangleHit;
            if (prim >= triangleCount ? primitives_->intersect(prim, ray, hit)
                                      : shearedRay.intersect(leafTriangles_[i], ray.tMax, &triangleHit))
                return true;  // any blocker will do
        }
    }
    return false;
}

template <int W>
StructureView WideBvhAccelerator<W>::structure() const {
    StructureView view;
    view.primIndices.assign(bvh_.primIndices.begin(), bvh_.primIndices.end());
    if (bvh_.nodes.empty()) return view;
    // Wide nodes keep their children's boxes, so a leaf becomes a view node of its own, made
    // where its parent lists it. Children are listed right after their parent is made.
    struct Pending {
        uint32_t viewIndex;
        uint32_t wideIndex;
    };
    std::vector<Pending> pending{{0, 0}};
    view.nodes.emplace_back();
    while (!pending.empty()) {
        auto [viewIndex, wideIndex] = pending.back();
        pending.pop_back();
        const WideBvhNode<W>& node = bvh_.nodes[wideIndex];
        StructureNode out;
        out.firstChild = static_cast<uint32_t>(view.children.size());
        for (int slot = 0; slot < W; ++slot) {
            bool isLeaf = node.child[slot] & kLeafFlag;
            if (isLeaf && node.primCount[slot] == 0) continue;  // an unused slot
            Bounds3f box;
            for (int axis = 0; axis < 3; ++axis) {
                box.lower[axis] = node.planes[WideBvhNode<W>::lowerRow(axis)][slot];
                box.upper[axis] = node.planes[WideBvhNode<W>::upperRow(axis)][slot];
            }
            out.bounds.extend(box);
            auto childIndex = static_cast<uint32_t>(view.nodes.size());
            view.children.push_back(childIndex);
            ++out.childCount;
            StructureNode child;
            child.bounds = box;
            if (isLeaf) {
                child.firstPrim = node.child[slot] & ~kLeafFlag;
                child.primCount = node.primCount[slot];
            } else {
                pending.push_back({childIndex, node.child[slot]});
            }
            view.nodes.push_back(child);
        }
        view.nodes[viewIndex] = out;
    }
    return view;
}

template <int W>
size_t WideBvhAccelerator<W>::memoryBytes() const {
    return bvh_.nodes.size() * sizeof(WideBvhNode<W>) + bvh_.primIndices.size() * sizeof(uint32_t) +
           leafTriangles_.size() * sizeof(leafTriangles_[0]);
}

template class WideBvhAccelerator<4>;
template class WideBvhAccelerator<8>;

}  // namespace rtlab
