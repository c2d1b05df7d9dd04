#include "framework/accel/kdtree/kdtree_adapter.h"

#include "framework/interface/a5_kdtree.h"

namespace rtlab {

KdTree KdTreeAdapter::build(const PrimitiveSet& primitives, const KdTreeOptions& options, KdBuilder builder) {
    return builder == KdBuilder::NlogN ? buildKdTreeNlogN(primitives.allBounds(), options) : buildKdTree(primitives.allBounds(), options);
}

bool KdTreeAdapter::intersect(const KdTree& tree, Traversal& traversal, Hit& hit) { return intersectKdTree(tree, traversal, hit); }

bool KdTreeAdapter::occluded(const KdTree& tree, Traversal& traversal) { return occludedKdTree(tree, traversal); }

}  // namespace rtlab
