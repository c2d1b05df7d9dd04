#include "fast/wide_bvh_accelerator.h"

#include "fast/point_view.h"
#include "fast/task_pool.h"
#include "framework/core/error.h"

#include <algorithm>
#include <atomic>
#include <new>

namespace rtlab {
namespace {

// Trees over fewer primitives are packed on one thread: starting threads would cost more.
constexpr uint32_t kParallelPacking = 16384;

}  // namespace

template <int W>
void WideBvhAccelerator<W>::build(const PrimitiveSet& primitives) {
    primitives_ = &primitives;
    hasSpheres_ = primitives.triangleCount() < primitives.size();
    WideBvh<W> wide = primitives.size() == 0 ? WideBvh<W>{} : makeTree_(primitives);

    // One block of memory: each node, then its leaves' packets of four, so that a leaf is read
    // from the lines after its parent's (WideBvhArrays). The block starts on a cache line
    // (HugePageAllocator), so nodes at even units are 64-byte aligned. A sphere takes a lane
    // with no triangle and is tested on its own. Every node's place is counted first, so the
    // nodes can be written on several threads, each byte once.
    constexpr uint32_t kNodeUnits = sizeof(WideBvhNode<W>) / kTreeUnit;
    constexpr uint32_t kPacketUnits = sizeof(TrianglePacket) / kTreeUnit;
    static_assert(sizeof(WideBvhNode<W>) % kTreeUnit == 0 && sizeof(TrianglePacket) % kTreeUnit == 0);
    constexpr uint32_t kNodeAlignment = alignof(WideBvhNode<W>) / kTreeUnit;
    std::vector<uint32_t> place(wide.nodes.size() + 1, 0);
    for (size_t i = 0; i < wide.nodes.size(); ++i) {
        uint32_t packets = 0;
        for (int slot = 0; slot < W; ++slot)
            if (wide.nodes[i].child[slot] & kLeafFlag) packets += packetCount(wide.nodes[i].primCount[slot]);
        uint32_t end = place[i] + kNodeUnits + packets * kPacketUnits;
        place[i + 1] = (end + kNodeAlignment - 1) / kNodeAlignment * kNodeAlignment;
    }
    if (place.back() >= kLeafFlag) throw Error("wide BVH: the tree is too large for 32-bit references");
    memory_.clear();
    memory_.resize(place.back());
    auto fill = [&](size_t firstNode, size_t lastNode) {
        for (size_t i = firstNode; i < lastNode; ++i) {
            WideBvhNode<W> node = wide.nodes[i];
            uint32_t packet = place[i] + kNodeUnits;
            for (int slot = 0; slot < W; ++slot) {
                if (!(node.child[slot] & kLeafFlag)) {
                    node.child[slot] = place[node.child[slot]];
                    continue;
                }
                if (node.primCount[slot] == 0) continue;
                const uint32_t* prims = wide.primIndices.data() + (node.child[slot] & ~kLeafFlag);
                node.child[slot] = kLeafFlag | packet;
                for (uint32_t begin = 0; begin < node.primCount[slot]; begin += TrianglePacket::kLanes, packet += kPacketUnits)
                    (new (memory_.data() + packet) TrianglePacket)->fill(
                        primitives, std::span(prims + begin, std::min<uint32_t>(TrianglePacket::kLanes, node.primCount[slot] - begin)));
            }
            new (memory_.data() + place[i]) WideBvhNode<W>(node);
        }
    };
    TaskPool pool(primitives.size() >= kParallelPacking ? packingThreads_ : 1);
    std::atomic<int> pending{0};
    size_t chunk = std::max<size_t>(1, wide.nodes.size() / (4 * size_t(pool.threads())));
    for (size_t first = 0; first < wide.nodes.size(); first += chunk)
        pool.run([&fill, first, chunk, &wide] { fill(first, std::min(first + chunk, wide.nodes.size())); }, pending);
    pool.waitFor(pending);
    arrays_ = {memory_.data(), &primitives};
    traversal_ = wideTraversal<W>(hasSpheres_);
}

template <int W>
Hit WideBvhAccelerator<W>::intersect(const Ray& ray, TraversalStats& stats) const {
    ++stats.rays;
    if (memory_.empty()) return Hit{};
    return traversal_.closestHit(arrays_, ray, stats);
}

template <int W>
bool WideBvhAccelerator<W>::occluded(const Ray& ray, TraversalStats& stats) const {
    ++stats.rays;
    if (memory_.empty()) return false;
    return traversal_.anyHit(arrays_, ray, stats);
}

template <int W>
std::unique_ptr<PointQueries> WideBvhAccelerator<W>::queriesAt(const Vec3& point) const {
    if (memory_.empty()) return nullptr;
    return PointView::make(*primitives_, point, *this);
}

template <int W>
StructureView WideBvhAccelerator<W>::structure() const {
    StructureView view;
    if (memory_.empty()) return view;
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
        const WideBvhNode<W>& node = arrays_.node(wideIndex);
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
                const TrianglePacket* packets = arrays_.packets(node.child[slot]);
                for (uint32_t i = 0; i < child.primCount; ++i)
                    view.primIndices.push_back(packets[i / TrianglePacket::kLanes].prim[i % TrianglePacket::kLanes]);
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
    return memory_.size() * sizeof(TreeUnit);
}

template class WideBvhAccelerator<4>;
template class WideBvhAccelerator<8>;

}  // namespace rtlab
