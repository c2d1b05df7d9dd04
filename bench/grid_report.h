// The grid's part of the bench report (docs/performance.md#grids): the targets of the uniform
// and two-level grids against the binary bvh-buckets:12 of the same run (grid_report.cpp
// registers them as the grid's target table, target_tables.h), and the plot of build and trace
// time against the grid's C.
#pragma once

#include "bench/throughput.h"

#include <ostream>
#include <string>
#include <vector>

namespace rtlab::bench {

// Build time and single-thread primary trace time against C (grid:C=1 .. 81), one line per
// scene, log-log. Writes nothing when no grid rows were measured.
void writeGridSweepSvg(const std::string& path, const std::vector<ThroughputRecord>& records);

}  // namespace rtlab::bench
