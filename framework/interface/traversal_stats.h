// Work counters the framework keeps for every query, one per counted operation of the
// Traversal context (traversal.h). Student code never touches them.
#pragma once

#include <cstdint>

namespace rtlab {

struct TraversalStats {
    uint64_t rays = 0;
    uint64_t nodeVisits = 0;      // box tests: BVH and octree nodes, the grid's bounds
    uint64_t cellSteps = 0;       // grid cells entered by the 3D-DDA, octree leaves entered
    uint64_t planeSteps = 0;      // split planes crossed or classified (KD-tree)
    uint64_t primitiveTests = 0;  // ray-primitive tests actually run
    uint64_t mailboxRepeats = 0;  // tests a mailbox skipped: the primitive was tested already

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
