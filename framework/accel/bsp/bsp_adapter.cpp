#include "framework/accel/bsp/bsp_adapter.h"

#include "framework/interface/a5_kdtree.h"

namespace rtlab {

BspTree BspAdapter::build(const PrimitiveSet& primitives, const BspOptions& options) {
    return buildBspAutopartition(primitives.allTriangles(), primitives.allBounds(), options);
}

bool BspAdapter::intersect(const BspTree& tree, Traversal& traversal, Hit& hit) { return intersectBsp(tree, traversal, hit); }

bool BspAdapter::occluded(const BspTree& tree, Traversal& traversal) { return occludedBsp(tree, traversal); }

}  // namespace rtlab
