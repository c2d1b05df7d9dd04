// Assignment a5, beyond the lecture: the O(N log N) build (optional).
//                                                  Guide: docs/a5-kdtree.md#building-in-on-log-n
//
// Contract (framework/interface/a5_kdtree.h): exactly buildKdTree's tree, bit for bit, but
//   kdSortedEvents is called once per axis, for the root's primitives. After kdClassify has
//   named each primitive's side, walk each axis's list in order and hand every event to the
//   child (or both children) its primitive goes to: the children's lists come out sorted.
//   Try it with `rtlab render --accel kdtree` (build=nlogn is the default) and compare the build
//   times: `rtlab bench --accel kdtree --accel kdtree:build=sort`.
//
// Hints:
//   * An array side[prim], filled while classifying, answers "where does this event go" in O(1).
//   * Free a node's event lists once its children have theirs: the deepest path holds the rest.
#include "framework/core/error.h"
#include "framework/interface/a5_kdtree.h"

namespace rtlab {

KdTree buildKdTreeNlogN(std::span<const Bounds3f> primBounds, const KdTreeOptions& options) {
    (void)primBounds, (void)options;
    throw NotImplemented("a5 buildKdTreeNlogN (assignments/a5_kdtree/kd_build_nlogn.cpp)");
}

}  // namespace rtlab
