// The grid's part of the bench report (docs/performance.md#grids): the targets of the uniform
// and two-level grids against the binary bvh-buckets:12 of the same run, and the plot of build
// and trace time against the grid's C.
#pragma once

#include "bench/throughput.h"

#include <ostream>
#include <string>
#include <vector>

namespace rtlab::bench {

// Targets, each where its scene was measured: on randsoup the grid builds at least 10x faster
// and traces primary rays at least 0.8x as fast (one line for the textbook grid:C=27, one for
// fast/'s fastgrid over the same cells); on the bunny at most 8 triangle tests per
// primary ray; on the stadium grid2 traces within 2x of the BVH.
void writeGridTargets(std::ostream& out, const std::vector<ThroughputRecord>& records);

// Build time and single-thread primary trace time against C (grid:C=1 .. 81), one line per
// scene, log-log. Writes nothing when no grid rows were measured.
void writeGridSweepSvg(const std::string& path, const std::vector<ThroughputRecord>& records);

}  // namespace rtlab::bench
