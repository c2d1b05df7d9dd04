#include "framework/accel/bvh_adapter.h"

#include "framework/interface/a1_bvh.h"

namespace rtlab {

std::vector<BuildPrimitive> buildPrimitivesOf(const PrimitiveSet& primitives) {
    std::vector<BuildPrimitive> prims;
    prims.reserve(primitives.size());  // not a sized vector: that would initialise every element first
    for (uint32_t i = 0; i < primitives.size(); ++i)
        prims.push_back(BuildPrimitive{primitives.bounds(i), primitives.centroid(i), i});
    return prims;
}

Bvh BvhAdapter::build(const PrimitiveSet& primitives, const BvhOptions& options) {
    return buildBvh(buildPrimitivesOf(primitives), options);
}

bool BvhAdapter::intersect(const Bvh& bvh, Traversal& traversal, Hit& hit) { return intersectBvh(bvh, traversal, hit); }

bool BvhAdapter::intersectRecursive(const Bvh& bvh, Traversal& traversal, Hit& hit) {
    return intersectBvhRecursive(bvh, traversal, hit);
}

bool BvhAdapter::occluded(const Bvh& bvh, Traversal& traversal) { return occludedBvh(bvh, traversal); }

}  // namespace rtlab
