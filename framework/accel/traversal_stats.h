// Work counters the framework keeps for every query: node visits (box tests) and primitive
// tests. Student code never touches them; the Traversal context increments them.
#pragma once

#include <cstdint>

namespace rtlab {

struct TraversalStats {
    uint64_t rays = 0;
    uint64_t nodeVisits = 0;
    uint64_t primitiveTests = 0;

    TraversalStats& operator+=(const TraversalStats& o) {
        rays += o.rays;
        nodeVisits += o.nodeVisits;
        primitiveTests += o.primitiveTests;
        return *this;
    }
};

}  // namespace rtlab
