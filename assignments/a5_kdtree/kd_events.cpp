// Assignment a5, part 2: events along an axis.     Guide: docs/a5-kdtree.md#events
//
// Contract (framework/interface/a5_kdtree.h, framework/interface/kdtree.h):
//   * kdEventBefore(a, b): a comes strictly before b when its position is smaller; at equal
//     positions when its type is smaller (End < Planar < Start); at equal types when its prim is
//     smaller.
//   * kdSortedEvents(prims, primBounds, axis): for each prim, with lo = primBounds[prim].lower[axis]
//     and hi = ...upper[axis]: lo == hi gives {lo, Planar, prim}, otherwise {lo, Start, prim} and
//     {hi, End, prim}; all of them sorted with kdEventBefore.
//
// Hints:
//   * std::sort takes the comparison: std::sort(events.begin(), events.end(), kdEventBefore).
//   * KdEventType's values are already in the pinned order (End = 0, Planar = 1, Start = 2).
#include "framework/core/error.h"
#include "framework/interface/a5_kdtree.h"

namespace rtlab {

bool kdEventBefore(const KdEvent& a, const KdEvent& b) {
    (void)a, (void)b;
    throw NotImplemented("a5 kdEventBefore (assignments/a5_kdtree/kd_events.cpp)");
}

std::vector<KdEvent> kdSortedEvents(std::span<const uint32_t> prims, std::span<const Bounds3f> primBounds, int axis) {
    (void)prims, (void)primBounds, (void)axis;
    throw NotImplemented("a5 kdSortedEvents (assignments/a5_kdtree/kd_events.cpp)");
}

}  // namespace rtlab
