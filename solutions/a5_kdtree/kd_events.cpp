// Reference solution: the events of primitive boxes along an axis, and their order
// (docs/a5-kdtree.md#events).
#include "framework/interface/a5_kdtree.h"

#include <algorithm>

namespace rtlab {

bool kdEventBefore(const KdEvent& a, const KdEvent& b) {
    // At one position, the boxes ending there come first, then those lying in the plane, then
    // those starting there: a sweep that has passed the Ends and Planars of p counts exactly
    // the boxes that lie on either side of a plane at p. The index makes the order total.
    if (a.position != b.position) return a.position < b.position;
    if (a.type != b.type) return a.type < b.type;
    return a.prim < b.prim;
}

std::vector<KdEvent> kdSortedEvents(std::span<const uint32_t> prims, std::span<const Bounds3f> primBounds, int axis) {
    std::vector<KdEvent> events;
    events.reserve(2 * prims.size());
    for (uint32_t prim : prims) {
        float lower = primBounds[prim].lower[axis], upper = primBounds[prim].upper[axis];
        if (lower == upper) {
            events.push_back({lower, KdEventType::Planar, prim});
        } else {
            events.push_back({lower, KdEventType::Start, prim});
            events.push_back({upper, KdEventType::End, prim});
        }
    }
    std::sort(events.begin(), events.end(), kdEventBefore);
    return events;
}

}  // namespace rtlab
