#include "framework/accel/wide_bvh_accelerator.h"

#include "framework/core/float_bits.h"
#include "framework/interface/a1_bvh.h"

#include <immintrin.h>

#include <bit>

namespace rtlab {
namespace {

// What the 4-wide slab test needs per ray, each value broadcast to all four lanes.
struct WideRay {
    __m128 origin[3];
    __m128 invDirection[3];
    __m128 tMin;
    // Per axis, the plane row the ray enters a box through and the one it leaves through:
    // lower then upper for a positive direction, the other way round for a negative one.
    int nearRow[3], farRow[3];

    explicit WideRay(const Ray& ray) : tMin(_mm_set1_ps(ray.tMin)) {
        RayInverse inverse(ray);
        for (int axis = 0; axis < 3; ++axis) {
            origin[axis] = _mm_set1_ps(inverse.origin[axis]);
            invDirection[axis] = _mm_set1_ps(inverse.invDirection[axis]);
            bool negative = inverse.dirIsNegative[axis];
            nearRow[axis] = negative ? WideBvhNode::upperRow(axis) : WideBvhNode::lowerRow(axis);
            farRow[axis] = negative ? WideBvhNode::lowerRow(axis) : WideBvhNode::upperRow(axis);
        }
    }
};

// The slab test of a0 on four boxes at once: per child, whether the segment (tMin, tMax]
// touches its box (all bits set in that lane) and where the ray enters it. Same arithmetic as
// the scalar test, including the enlarged far distance.
struct ChildHits {
    __m128 tEnter;
    __m128 hit;
};

inline ChildHits intersectChildren(const WideBvhNode& node, const WideRay& ray, float tMax) {
    const __m128 farScale = _mm_set1_ps(1.0f + 2.0f * gamma(3));
    __m128 tNear = ray.tMin, tFar = _mm_set1_ps(tMax);
    for (int axis = 0; axis < 3; ++axis) {
        __m128 t0 = (_mm_load_ps(node.planes[ray.nearRow[axis]]) - ray.origin[axis]) * ray.invDirection[axis];
        __m128 t1 = (_mm_load_ps(node.planes[ray.farRow[axis]]) - ray.origin[axis]) * ray.invDirection[axis];
        // MAXPS and MINPS return their second operand when either is NaN (0 * inf: the origin
        // on a slab plane, direction 0 on that axis), so NaN leaves the interval as it was.
        tNear = _mm_max_ps(t0, tNear);
        tFar = _mm_min_ps(t1 * farScale, tFar);
    }
    return {tNear, _mm_cmple_ps(tNear, tFar)};
}

// A child waiting to be visited.
struct StackEntry {
    uint32_t ref;  // interior node index, or kLeafFlag | first primIndices entry
    uint32_t primCount;
    float tEnter;
};
// Every wide node on the current path leaves at most three siblings on the stack, and a wide
// tree is no deeper than its binary tree; the last node's four children are written in place.
constexpr int kStackSize = (kWideBvhWidth - 1) * kMaxBvhDepth + kWideBvhWidth;

// Writes the children the ray hits to out, farthest first, so the nearest is out[count - 1].
// Returns count. An insertion sort: most nodes have one or two children hit. (A branch-free
// version, sorting integer keys with a min/max network, mispredicted half as often but ran
// slower on primary rays: docs/performance.md.)
inline int orderChildren(const WideBvhNode& node, ChildHits hits, StackEntry* out) {
    alignas(16) float distances[kWideBvhWidth];
    _mm_store_ps(distances, hits.tEnter);
    int count = 0;
    for (int mask = _mm_movemask_ps(hits.hit); mask != 0; mask &= mask - 1) {
        int slot = std::countr_zero(static_cast<unsigned>(mask));
        out[count++] = {node.child[slot], node.primCount[slot], distances[slot]};
    }
    for (int i = 1; i < count; ++i)
        for (int j = i; j > 0 && out[j - 1].tEnter < out[j].tEnter; --j) std::swap(out[j - 1], out[j]);
    return count;
}

}  // namespace

void WideBvhAccelerator::build(const PrimitiveSet& primitives) {
    primitives_ = &primitives;
    std::vector<BuildPrimitive> prims(primitives.size());
    for (uint32_t i = 0; i < primitives.size(); ++i)
        prims[i] = BuildPrimitive{primitives.bounds(i), primitives.centroid(i), i};
    bvh_ = prims.empty() ? WideBvh{} : collapseToWide(buildBvh(std::move(prims), options_));

    leafTriangles_.resize(bvh_.primIndices.size());
    for (size_t i = 0; i < bvh_.primIndices.size(); ++i)
        if (bvh_.primIndices[i] < primitives.triangleCount())
            leafTriangles_[i] = coordinatesOf(primitives.triangle(bvh_.primIndices[i]));
}

Hit WideBvhAccelerator::intersect(const Ray& ray, TraversalStats& stats) const {
    ++stats.rays;
    Hit hit;
    hit.t = ray.tMax;
    if (bvh_.nodes.empty()) return Hit{};

    const WideRay wideRay(ray);
    const ShearedRay shearedRay(ray);
    const uint32_t triangleCount = primitives_->triangleCount();
    uint64_t nodeVisits = 0, primitiveTests = 0;
    StackEntry stack[kStackSize];
    int stackSize = 0;
    StackEntry current{0, 0, ray.tMin};
    for (;;) {
        if (!(current.ref & kLeafFlag)) {
            const WideBvhNode& node = bvh_.nodes[current.ref];
            ++nodeVisits;
            // The hit children go onto the stack, the nearest on top; it is visited next, the
            // others wait, farthest deepest.
            StackEntry* pushed = stack + stackSize;
            int count = orderChildren(node, intersectChildren(node, wideRay, hit.t), pushed);
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

bool WideBvhAccelerator::occluded(const Ray& ray, TraversalStats& stats) const {
    ++stats.rays;
    if (bvh_.nodes.empty()) return false;

    const WideRay wideRay(ray);
    const ShearedRay shearedRay(ray);
    const uint32_t triangleCount = primitives_->triangleCount();
    StackEntry stack[kStackSize];
    int stackSize = 0;
    stack[stackSize++] = StackEntry{0, 0, ray.tMin};
    while (stackSize > 0) {
        StackEntry current = stack[--stackSize];
        if (!(current.ref & kLeafFlag)) {
            const WideBvhNode& node = bvh_.nodes[current.ref];
            ++stats.nodeVisits;
            stackSize += orderChildren(node, intersectChildren(node, wideRay, ray.tMax), stack + stackSize);
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

StructureView WideBvhAccelerator::structure() const {
    StructureView view;
    view.primIndices = bvh_.primIndices;
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
        const WideBvhNode& node = bvh_.nodes[wideIndex];
        StructureNode out;
        out.firstChild = static_cast<uint32_t>(view.children.size());
        for (int slot = 0; slot < kWideBvhWidth; ++slot) {
            bool isLeaf = node.child[slot] & kLeafFlag;
            if (isLeaf && node.primCount[slot] == 0) continue;  // an unused slot
            Bounds3f box;
            for (int axis = 0; axis < 3; ++axis) {
                box.lower[axis] = node.planes[WideBvhNode::lowerRow(axis)][slot];
                box.upper[axis] = node.planes[WideBvhNode::upperRow(axis)][slot];
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

size_t WideBvhAccelerator::memoryBytes() const {
    return bvh_.nodes.size() * sizeof(WideBvhNode) + bvh_.primIndices.size() * sizeof(uint32_t) +
           leafTriangles_.size() * sizeof(leafTriangles_[0]);
}

}  // namespace rtlab
