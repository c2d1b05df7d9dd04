// Work counters the framework keeps for every query, one per counted operation of the
// Traversal context (traversal.h). Student code never touches them.
#pragma once

#include <cstdint>

namespace rtlab {

struct TraversalTrace;  // traversal_trace.h

struct TraversalStats {
    uint64_t rays = 0;
    uint64_t nodeVisits = 0;      // box tests: BVH and octree nodes, the grid's bounds
    uint64_t cellSteps = 0;       // grid cells entered by the 3D-DDA, octree leaves entered
    uint64_t planeSteps = 0;      // split planes crossed or classified (KD-tree)
    uint64_t primitiveTests = 0;  // ray-primitive tests actually run
    uint64_t mailboxRepeats = 0;  // tests a mailbox skipped: the primitive was tested already
    // Where a Traversal made with these stats records its operations in order (null, the
    // default: nowhere). The viewer and the grader's worker set it for the queries they show;
    // it rides on the stats because every accelerator hands them to its Traversal, so tracing
    // needs no change to any structure or to student code. Not summed by +=.
    TraversalTrace* trace = nullptr;

    // The structure's own work: every box test, cell step and plane step.
    uint64_t steps() const { return nodeVisits + cellSteps + planeSteps; }

    TraversalStats& operator+=(const TraversalStats& o) {
        rays += o.rays;
        nodeVisits += o.nodeVisits;
        cellSteps += o.cellSteps;
        planeSteps += o.planeSteps;
        primitiveTests += o.primitiveTests;
        mailboxRepeats += o.mailboxRepeats;
        return *this;
    }
};

}  // namespace rtlab
