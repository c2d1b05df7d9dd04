// The comparison of the lecture's structures on the same scenes (docs/structures-compared.md): build time
// against trace time, one point per structure, so the "time to image" trade-off of spatial and
// object partitions can be read off one chart.
#pragma once

#include "bench/throughput.h"

#include <string>
#include <vector>

namespace rtlab::bench {

// Log-log: build ms (x) against the single-thread time to trace one million primary rays (y),
// one series per scene, each point labelled with its structure (the rtlab rows and Embree
// MEDIUM). Writes nothing when fewer than two structures were measured on any scene.
void writeStructuresSvg(const std::string& path, const std::vector<ThroughputRecord>& records);

}  // namespace rtlab::bench
