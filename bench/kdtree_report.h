// The KD-tree's part of the bench report (docs/performance.md#kd-trees): its targets against the
// binary bvh-buckets:12 and its own per-node-sort build, all from the same run.
#pragma once

#include "bench/throughput.h"

#include <ostream>
#include <vector>

namespace rtlab::bench {

// Targets, each where its scene was measured: at most 6 triangle tests per primary ray on the
// bunny, the engine and the sphereflake; primary throughput at least 1.0x bvh-buckets:12 on the
// engine; on the sphereflake the O(N log N) build at least 4x faster than the per-node sort.
void writeKdTreeTargets(std::ostream& out, const std::vector<ThroughputRecord>& records);

}  // namespace rtlab::bench
