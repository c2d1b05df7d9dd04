// Registers embreetree: the eight-wide BVH that Embree's own builder makes (rtcBuildBVH, binned
// SAH, the settings of its BVH8 over blocks of four triangles), walked by fast/'s traversal. Next
// to fastbvh it says whether what is left between rtlab and Embree is the tree or the walk
// (docs/performance.md, "Embree's tree under rtlab's walk"). Only the bench links Embree, so the
// structure exists only there.
#include "fast/wide_bvh_accelerator.h"
#include "framework/accel/accelerator_registry.h"
#include "framework/core/error.h"

#include <embree3/rtcore.h>

#include <cstdint>
#include <string>
#include <vector>

namespace rtlab::bench {
namespace {

// What Embree's callbacks build, in its thread-local memory, before it becomes a WideBvh.
struct BuiltNode {
    bool leaf;
    uint32_t count;  // children, or primitives of a leaf
};
struct BuiltInterior : BuiltNode {
    BuiltNode* children[8];
    RTCBounds bounds[8];
};
struct BuiltLeaf : BuiltNode {
    uint32_t prims[1];  // count of them
};

void* createInterior(RTCThreadLocalAllocator allocator, unsigned childCount, void*) {
    auto* node = static_cast<BuiltInterior*>(rtcThreadLocalAlloc(allocator, sizeof(BuiltInterior), 16));
    node->leaf = false;
    node->count = childCount;
    return node;
}

void setChildren(void* node, void** children, unsigned count, void*) {
    for (unsigned i = 0; i < count; ++i) static_cast<BuiltInterior*>(node)->children[i] = static_cast<BuiltNode*>(children[i]);
}

void setBounds(void* node, const RTCBounds** bounds, unsigned count, void*) {
    for (unsigned i = 0; i < count; ++i) static_cast<BuiltInterior*>(node)->bounds[i] = *bounds[i];
}

void* createLeaf(RTCThreadLocalAllocator allocator, const RTCBuildPrimitive* prims, size_t count, void*) {
    auto* leaf = static_cast<BuiltLeaf*>(rtcThreadLocalAlloc(allocator, sizeof(BuiltLeaf) + count * sizeof(uint32_t), 16));
    leaf->leaf = true;
    leaf->count = uint32_t(count);
    for (size_t i = 0; i < count; ++i) leaf->prims[i] = prims[i].primID;
    return leaf;
}

// Lays Embree's tree out as buildWideBvh does: a node's interior children side by side, each
// filled depth first.
class Layout {
public:
    explicit Layout(WideBvh<8>& wide) : wide_(wide) {}

    void fill(const BuiltInterior& built, uint32_t index) {
        uint32_t interior = 0;
        for (uint32_t i = 0; i < built.count; ++i) interior += !built.children[i]->leaf;
        uint32_t first = uint32_t(wide_.nodes.size());
        wide_.nodes.resize(first + interior);
        uint32_t next = first;
        for (int slot = 0; slot < 8; ++slot) {
            WideBvhNode<8>& node = wide_.nodes[index];
            if (slot >= int(built.count)) {
                node.setEmpty(slot);
                continue;
            }
            const RTCBounds& b = built.bounds[slot];
            Bounds3f box(Vec3(b.lower_x, b.lower_y, b.lower_z), Vec3(b.upper_x, b.upper_y, b.upper_z));
            const BuiltNode* child = built.children[slot];
            if (child->leaf) {
                auto start = uint32_t(wide_.primIndices.size());
                const auto* leaf = static_cast<const BuiltLeaf*>(child);
                wide_.primIndices.insert(wide_.primIndices.end(), leaf->prims, leaf->prims + leaf->count);
                node.setChild(slot, box, kLeafFlag | start, leaf->count);
            } else {
                node.setChild(slot, box, next++, 0);
            }
        }
        next = first;
        for (uint32_t i = 0; i < built.count; ++i)
            if (!built.children[i]->leaf) fill(*static_cast<const BuiltInterior*>(built.children[i]), next++);
    }

private:
    WideBvh<8>& wide_;
};

WideBvh<8> embreeTree(const PrimitiveSet& primitives, int maxLeaf) {
    RTCDevice device = rtcNewDevice("threads=1");
    if (!device) throw Error("embree: rtcNewDevice failed");
    const auto bounds = primitives.allBounds();
    std::vector<RTCBuildPrimitive> prims(primitives.size());
    for (uint32_t i = 0; i < primitives.size(); ++i) {
        const Bounds3f& b = bounds[i];
        prims[i] = RTCBuildPrimitive{b.lower.x, b.lower.y, b.lower.z, 0, b.upper.x, b.upper.y, b.upper.z, i};
    }
    RTCBVH bvh = rtcNewBVH(device);
    RTCBuildArguments args = rtcDefaultBuildArguments();
    args.buildQuality = RTC_BUILD_QUALITY_MEDIUM;
    args.maxBranchingFactor = 8;
    args.maxDepth = kMaxBvhDepth - 1;
    args.sahBlockSize = 4;
    args.minLeafSize = 4;
    args.maxLeafSize = uint32_t(maxLeaf);
    args.bvh = bvh;
    args.primitives = prims.data();
    args.primitiveCount = prims.size();
    args.primitiveArrayCapacity = prims.size();
    args.createNode = createInterior;
    args.setNodeChildren = setChildren;
    args.setNodeBounds = setBounds;
    args.createLeaf = createLeaf;
    const auto* root = static_cast<const BuiltNode*>(rtcBuildBVH(&args));
    if (!root) {
        rtcReleaseBVH(bvh);
        rtcReleaseDevice(device);
        throw Error("embree: rtcBuildBVH failed");
    }

    WideBvh<8> wide;
    wide.nodes.resize(1);
    if (root->leaf) {
        BuiltInterior single{};
        single.leaf = false;
        single.count = 1;
        single.children[0] = const_cast<BuiltNode*>(root);
        Bounds3f all;
        for (const Bounds3f& b : bounds) all.extend(b);
        single.bounds[0] = RTCBounds{all.lower.x, all.lower.y, all.lower.z, 0, all.upper.x, all.upper.y, all.upper.z, 0};
        Layout(wide).fill(single, 0);
    } else {
        Layout(wide).fill(*static_cast<const BuiltInterior*>(root), 0);
    }
    rtcReleaseBVH(bvh);
    rtcReleaseDevice(device);
    return wide;
}

AcceleratorType embreeTreeType() {
    return {"embreetree",
            "Embree's binned-SAH builder (rtcBuildBVH) for fast/'s eight-wide traversal (bench only)",
            {{"leaf", "largest leaf (triangles)", "8", 4, RTC_BUILD_MAX_PRIMITIVES_PER_LEAF, true, {}}},
            [](const AcceleratorParameters& p) -> std::unique_ptr<Accelerator> {
                int maxLeaf = p.integer("leaf");
                return std::make_unique<WideBvhAccelerator<8>>(
                    [maxLeaf](const PrimitiveSet& prims) { return embreeTree(prims, maxLeaf); }, 0);
            },
            {"embreetree"},
            0};
}

const AcceleratorRegistration kEmbreeTree{embreeTreeType()};

}  // namespace
}  // namespace rtlab::bench
