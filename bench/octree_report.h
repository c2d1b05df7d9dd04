// The octree's part of the bench report (docs/performance.md#octrees): its memory target (at most
// 20 references per triangle on the engine, where bounding-box insertion stores 153) and the
// same figure for every octree row measured.
#pragma once

#include "bench/throughput.h"

#include <ostream>
#include <vector>

namespace rtlab::bench {

// Writes nothing when no octree row was measured.
void writeOctreeTargets(std::ostream& out, const std::vector<ThroughputRecord>& records);

}  // namespace rtlab::bench
