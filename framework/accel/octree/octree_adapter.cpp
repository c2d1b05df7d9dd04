#include "framework/accel/octree/octree_adapter.h"

#include "framework/interface/a4_octree.h"

namespace rtlab {

Octree OctreeAdapter::build(const PrimitiveSet& primitives, const OctreeOptions& options) {
    return buildOctree(OctreeInput{primitives.allBounds(), primitives.allTriangles()}, options);
}

bool OctreeAdapter::intersect(const Octree& octree, Traversal& traversal, Hit& hit) { return intersectOctree(octree, traversal, hit); }

bool OctreeAdapter::occluded(const Octree& octree, Traversal& traversal) { return occludedOctree(octree, traversal); }

}  // namespace rtlab
