#include "fast/wide_bvh_accelerator.h"

#include "fast/point_view.h"
#include "fast/simd.h"
#include "fast/task_pool.h"
#include "framework/core/float_bits.h"
#include "framework/interface/a1_bvh.h"

#include <algorithm>
#include <atomic>
#include <bit>
#include <cstring>

namespace rtlab {
namespace {

template <int W>
using Lanes = Simd<float, W>;

// a0's enlargement of the far distance, so that rounding never shrinks a box (Ize 2013,
// docs/conventions.md).
constexpr float kFarScale = 1.0f + 2.0f * gamma(3);

// What the W-wide slab test needs per ray, each value broadcast to all lanes.
template <int W>
struct WideRay {
    Lanes<W> origin[3];
    Lanes<W> invDirection[3];
    // The reciprocal times kFarScale, for the far planes. a0 rounds four times and then
    // scales: (p - o), 1 / d, the product, the product with kFarScale. This rounds four times
    // with the scale inside; either way the far distance is at least kFarScale (1 - u)^4 > 1
    // times the exact one, so no box the ray touches is missed.
    Lanes<W> farInvDirection[3];
    Lanes<W> tMin;
    // Per axis, the plane row the ray enters a box through and the one it leaves through:
    // lower then upper for a positive direction, the other way round for a negative one.
    int nearRow[3], farRow[3];

    explicit WideRay(const Ray& ray) : tMin(broadcast<W>(ray.tMin)) {
        RayInverse inverse(ray);
        for (int axis = 0; axis < 3; ++axis) {
            origin[axis] = broadcast<W>(inverse.origin[axis]);
            invDirection[axis] = broadcast<W>(inverse.invDirection[axis]);
            farInvDirection[axis] = broadcast<W>(inverse.invDirection[axis] * kFarScale);
            bool negative = inverse.dirIsNegative[axis];
            nearRow[axis] = negative ? WideBvhNode<W>::upperRow(axis) : WideBvhNode<W>::lowerRow(axis);
            farRow[axis] = negative ? WideBvhNode<W>::lowerRow(axis) : WideBvhNode<W>::upperRow(axis);
        }
    }
};

// The slab test of a0 on W boxes at once: per child, where the ray enters its box and whether
// the segment (tMin, tMax] touches it. The near distances are a0's arithmetic exactly; the far
// ones are enlarged as a0 enlarges them, with the factor folded into the reciprocal once per
// ray (WideRay::farInvDirection).
template <int W>
struct ChildHits {
    Lanes<W> tEnter;
    SimdMask<W> hit;
};

template <int W>
ChildHits<W> intersectChildren(const WideBvhNode<W>& node, const WideRay<W>& ray, float tMax) {
    Lanes<W> tNear = ray.tMin, tFar = broadcast<W>(tMax);
    for (int axis = 0; axis < 3; ++axis) {
        Lanes<W> t0 = (load<W>(node.planes[ray.nearRow[axis]]) - ray.origin[axis]) * ray.invDirection[axis];
        Lanes<W> t1 = (load<W>(node.planes[ray.farRow[axis]]) - ray.origin[axis]) * ray.farInvDirection[axis];
        // A NaN distance (0 * inf: the origin on a slab plane, direction 0 on that axis) fails
        // the comparison and leaves the interval as it was. This is max and min (MAXPS/MINPS).
        tNear = t0 > tNear ? t0 : tNear;
        tFar = t1 < tFar ? t1 : tFar;
    }
    return {tNear, tNear <= tFar};
}

// Trees over fewer primitives are packed on one thread: starting threads would cost more.
constexpr uint32_t kParallelPacking = 16384;

// How many packets a leaf of primCount primitives fills.
uint32_t packetCount(uint32_t primCount) {
    return (primCount + TrianglePacket::kLanes - 1) / TrianglePacket::kLanes;
}

// A child waiting to be visited.
struct StackEntry {
    uint32_t ref;  // interior node index, or kLeafFlag | first packet
    uint32_t primCount;
    float tEnter;
};

// Every wide node on the current path leaves at most W - 1 siblings on the stack, and a wide
// tree is no deeper than its binary tree; the last node's W children are written in place.
template <int W>
constexpr int kStackSize = (W - 1) * kMaxBvhDepth + W;

// The child to visit next at a node whose hit children are the bits of mask (not none): the
// nearest. The others wait on the stack, the farthest deepest; of equally near children the
// one in the later slot is visited first. One or two children are hit at most nodes, and
// those cases take no loop.
template <int W>
inline StackEntry nearestChild(const WideBvhNode<W>& node, const ChildHits<W>& hits, unsigned mask, StackEntry* stack,
                               int& stackSize) {
    auto entry = [&node](int slot, float tEnter) { return StackEntry{node.child[slot], node.primCount[slot], tEnter}; };
    int first = std::countr_zero(mask);
    unsigned rest = mask & (mask - 1);
    if (rest == 0) return entry(first, 0.0f);  // only waiting children need their entry distance

    float tEnter[W];
    std::memcpy(tEnter, &hits.tEnter, sizeof tEnter);  // one store instead of a shuffle per lane
    int second = std::countr_zero(rest);
    if ((rest & (rest - 1)) == 0) {
        bool firstNearer = tEnter[first] < tEnter[second];
        int nearer = firstNearer ? first : second, farther = firstNearer ? second : first;
        stack[stackSize++] = entry(farther, tEnter[farther]);
        return entry(nearer, tEnter[nearer]);
    }
    // Three or more: all onto the stack in slot order, an insertion sort, and the top is next.
    StackEntry* out = stack + stackSize;
    int count = 0;
    for (; mask != 0; mask &= mask - 1) {
        int slot = std::countr_zero(mask);
        out[count++] = entry(slot, tEnter[slot]);
    }
    for (int i = 1; i < count; ++i)
        for (int j = i; j > 0 && out[j - 1].tEnter < out[j].tEnter; --j) std::swap(out[j - 1], out[j]);
    stackSize += count - 1;
    return out[count - 1];
}

}  // namespace

template <int W>
void WideBvhAccelerator<W>::build(const PrimitiveSet& primitives) {
    primitives_ = &primitives;
    hasSpheres_ = primitives.triangleCount() < primitives.size();
    WideBvh<W> wide = primitives.size() == 0 ? WideBvh<W>{} : makeTree_(primitives);

    // Each leaf's primitives go into packets of four, a node's leaves one after the other in the
    // order the nodes are stored, so a leaf reads consecutive memory. A sphere takes a lane with
    // no triangle and is tested on its own. The packets of each node are counted first, so the
    // nodes can be filled on several threads, each packet written once.
    std::vector<uint32_t> firstPacket(wide.nodes.size() + 1, 0);
    for (size_t i = 0; i < wide.nodes.size(); ++i) {
        uint32_t count = 0;
        for (int slot = 0; slot < W; ++slot)
            if (wide.nodes[i].child[slot] & kLeafFlag) count += packetCount(wide.nodes[i].primCount[slot]);
        firstPacket[i + 1] = firstPacket[i] + count;
    }
    packets_.clear();
    packets_.resize(firstPacket.back());
    auto fill = [&](size_t firstNode, size_t lastNode) {
        for (size_t i = firstNode; i < lastNode; ++i) {
            WideBvhNode<W>& node = wide.nodes[i];
            uint32_t packet = firstPacket[i];
            for (int slot = 0; slot < W; ++slot) {
                if (!(node.child[slot] & kLeafFlag) || node.primCount[slot] == 0) continue;
                const uint32_t* prims = wide.primIndices.data() + (node.child[slot] & ~kLeafFlag);
                node.child[slot] = kLeafFlag | packet;
                for (uint32_t begin = 0; begin < node.primCount[slot]; begin += TrianglePacket::kLanes)
                    packets_[packet++].fill(primitives, std::span(prims + begin, std::min<uint32_t>(TrianglePacket::kLanes, node.primCount[slot] - begin)));
            }
        }
    };
    TaskPool pool(primitives.size() >= kParallelPacking ? packingThreads_ : 1);
    std::atomic<int> pending{0};
    size_t chunk = std::max<size_t>(1, wide.nodes.size() / (4 * size_t(pool.threads())));
    for (size_t first = 0; first < wide.nodes.size(); first += chunk)
        pool.run([&fill, first, chunk, &wide] { fill(first, std::min(first + chunk, wide.nodes.size())); }, pending);
    pool.waitFor(pending);
    nodes_ = std::move(wide.nodes);
}

template <int W>
bool WideBvhAccelerator<W>::intersectSpheres(const TrianglePacket& packet, const Ray& ray, Hit& hit) const {
    bool found = false;
    for (uint32_t prim : packet.prim)
        if (prim != kNoPrimitive && prim >= primitives_->triangleCount()) found |= primitives_->intersect(prim, ray, hit);
    return found;
}

template <int W>
Hit WideBvhAccelerator<W>::intersect(const Ray& ray, TraversalStats& stats) const {
    ++stats.rays;
    if (nodes_.empty()) return Hit{};
    return hasSpheres_ ? closestHit<true>(ray, stats) : closestHit<false>(ray, stats);
}

template <int W>
bool WideBvhAccelerator<W>::occluded(const Ray& ray, TraversalStats& stats) const {
    ++stats.rays;
    if (nodes_.empty()) return false;
    return hasSpheres_ ? anyHit<true>(ray, stats) : anyHit<false>(ray, stats);
}

template <int W>
std::unique_ptr<PointQueries> WideBvhAccelerator<W>::queriesAt(const Vec3& point) const {
    if (nodes_.empty()) return nullptr;
    return PointView::make(*primitives_, point, *this);
}

template <int W>
template <bool kSpheres>
Hit WideBvhAccelerator<W>::closestHit(const Ray& ray, TraversalStats& stats) const {
    Hit hit;
    hit.t = ray.tMax;

    const WideRay<W> wideRay(ray);
    const ShearedRay shearedRay(ray);
    uint64_t nodeVisits = 0, primitiveTests = 0;
    StackEntry stack[kStackSize<W>];
    int stackSize = 0;
    StackEntry current{0, 0, ray.tMin};
    for (;;) {
        if (!(current.ref & kLeafFlag)) {
            const WideBvhNode<W>& node = nodes_[current.ref];
            ++nodeVisits;
            ChildHits<W> hits = intersectChildren<W>(node, wideRay, hit.t);
            if (unsigned mask = laneBits<W>(hits.hit); mask != 0) {
                current = nearestChild<W>(node, hits, mask, stack, stackSize);
                continue;
            }
        } else {
            uint32_t first = current.ref & ~kLeafFlag;
            primitiveTests += current.primCount;
            for (uint32_t p = first; p < first + packetCount(current.primCount); ++p) {
                const TrianglePacket& packet = packets_[p];
                if (PacketHit nearest = shearedRay.closest(packet, hit.t); nearest.lane >= 0)
                    hit = Hit{nearest.hit.t, packet.prim[nearest.lane], nearest.hit.b1, nearest.hit.b2};
                if constexpr (kSpheres) intersectSpheres(packet, ray, hit);
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
template <bool kSpheres>
bool WideBvhAccelerator<W>::anyHit(const Ray& ray, TraversalStats& stats) const {
    const WideRay<W> wideRay(ray);
    const ShearedRay shearedRay(ray);
    uint64_t nodeVisits = 0, primitiveTests = 0;
    bool blocked = false;
    // Any blocker will do, so the children a ray hits are not sorted: the first is visited next,
    // the others wait in slot order, and no entry distance is kept.
    StackEntry stack[kStackSize<W>];
    int stackSize = 0;
    StackEntry current{0, 0, 0.0f};
    for (;;) {
        if (!(current.ref & kLeafFlag)) {
            const WideBvhNode<W>& node = nodes_[current.ref];
            ++nodeVisits;
            ChildHits<W> hits = intersectChildren<W>(node, wideRay, ray.tMax);
            if (unsigned mask = laneBits<W>(hits.hit); mask != 0) {
                int slot = std::countr_zero(mask);
                current = StackEntry{node.child[slot], node.primCount[slot], 0.0f};
                for (mask &= mask - 1; mask != 0; mask &= mask - 1) {
                    slot = std::countr_zero(mask);
                    stack[stackSize++] = StackEntry{node.child[slot], node.primCount[slot], 0.0f};
                }
                continue;
            }
        } else {
            uint32_t first = current.ref & ~kLeafFlag;
            primitiveTests += current.primCount;
            for (uint32_t p = first; p < first + packetCount(current.primCount) && !blocked; ++p) {
                blocked = shearedRay.anyHit(packets_[p], ray.tMax);
                if constexpr (kSpheres) {
                    Hit hit;
                    hit.t = ray.tMax;
                    blocked = blocked || intersectSpheres(packets_[p], ray, hit);
                }
            }
        }
        if (blocked || stackSize == 0) break;
        current = stack[--stackSize];
    }
    stats.nodeVisits += nodeVisits;
    stats.primitiveTests += primitiveTests;
    return blocked;
}

template <int W>
StructureView WideBvhAccelerator<W>::structure() const {
    StructureView view;
    if (nodes_.empty()) return view;
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
        const WideBvhNode<W>& node = nodes_[wideIndex];
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
                child.firstPrim = static_cast<uint32_t>(view.primIndices.size());
                child.primCount = node.primCount[slot];
                uint32_t firstPacket = node.child[slot] & ~kLeafFlag;
                for (uint32_t i = 0; i < child.primCount; ++i)
                    view.primIndices.push_back(packets_[firstPacket + i / TrianglePacket::kLanes].prim[i % TrianglePacket::kLanes]);
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
    return nodes_.size() * sizeof(WideBvhNode<W>) + packets_.size() * sizeof(TrianglePacket);
}

template class WideBvhAccelerator<4>;
template class WideBvhAccelerator<8>;

}  // namespace rtlab
