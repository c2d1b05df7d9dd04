// The operations of one query, in the order the traversal did them: what the viewer steps
// through (docs/viewer.md) and what a failing grader case can carry to it. Recording is opt-in:
// a Traversal records only when its TraversalStats point at a trace (traversal_stats.h), so
// rendering and grading pay one untaken branch per operation and nothing else. Student code
// never sees it; the counted operations of traversal.h fill it.
//
// Every entry is numbers only, and the list is capped: a traversal that loops forever fills the
// trace up to `capacity` and then only counts what it dropped.
#pragma once

#include "framework/core/bounds.h"

#include <cstdint>
#include <vector>

namespace rtlab {

// One kind per counted operation of the Traversal context.
enum class TraceOpKind : uint8_t {
    BoxTest = 0,        // hitsBox: index = the box's position in TraversalTrace::boxes
    CellStep = 1,       // countCellStep: a grid cell entered (the context is not told which)
    LeafEntry = 2,      // enterLeaf: index = the node
    PlaneStep = 3,      // countPlaneStep: a split plane classified (the context is not told which)
    PrimitiveTest = 4,  // intersect / occludes: index = the primitive
    MailboxRepeat = 5,  // a primitive the mailbox had seen: index = the primitive, not tested again
};
inline constexpr int kTraceOpKinds = 6;
inline constexpr uint32_t kTraceNoIndex = 0xffffffffu;

// 16 bytes, no padding, so a trace travels as a plain array (traversal_trace_format.h).
struct TraceOp {
    TraceOpKind kind = TraceOpKind::CellStep;
    uint8_t hit = 0;         // box test: the box was hit; primitive test: the primitive was hit
    uint16_t reserved = 0;   // zero
    uint32_t index = kTraceNoIndex;
    float t = 0.0f;          // box test: the entry distance on a hit; primitive test: the hit's t
    float tFar = 0.0f;       // box test: the segment's end it was asked about; primitive test:
                             // the closest hit so far before the test (the ray's tMax at first)
};
static_assert(sizeof(TraceOp) == 16, "a trace entry is four words");

// The default cap: enough for any query of a correct structure on the committed scenes (a
// brute-force ray through the bunny tests 69 451 primitives, so that one is cut).
inline constexpr uint32_t kTraceDefaultCapacity = 1u << 16;

struct TraversalTrace {
    std::vector<TraceOp> ops;
    std::vector<Bounds3f> boxes;  // one per BoxTest, in order
    uint32_t capacity = kTraceDefaultCapacity;
    uint64_t dropped = 0;  // operations after the cap: counted, not kept

    bool truncated() const { return dropped > 0; }
    void clear() {
        ops.clear();
        boxes.clear();
        dropped = 0;
    }

    void add(const TraceOp& op) {
        if (ops.size() >= capacity) {
            ++dropped;
            return;
        }
        ops.push_back(op);
    }
    void addBox(const Bounds3f& box, bool hit, float tEnter, float tFar) {
        if (ops.size() >= capacity) {
            ++dropped;
            return;
        }
        ops.push_back(TraceOp{TraceOpKind::BoxTest, uint8_t(hit), 0, static_cast<uint32_t>(boxes.size()), hit ? tEnter : 0.0f, tFar});
        boxes.push_back(box);
    }
};

}  // namespace rtlab
