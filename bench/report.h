// Output of the throughput benchmark: a Markdown table per scene for the terminal and
// docs/performance.md, and results.csv (one row per scene, system, ray set and thread count).
#pragma once

#include "bench/throughput.h"

#include <ostream>
#include <string>
#include <vector>

namespace rtlab::bench {

void writeMarkdown(std::ostream& out, const std::vector<ThroughputRecord>& records);

// Columns: scene,triangles,system,rays,threads,build_ms,mrays_per_s,ratio_to_embree_medium,
// sah_cost,node_visits_per_ray,prim_tests_per_ray,bytes_per_triangle,mismatches,hits,sum_t,
// load_average,note,cell_steps_per_ray,plane_steps_per_ray,references_per_triangle. Empty fields
// where a figure does not exist.
void writeCsv(const std::string& path, const std::vector<ThroughputRecord>& records);

// The target of issue 6 (docs/performance.md): per scene, the best rtlab BVH's single-thread
// ratio to Embree MEDIUM (>= 0.7 primary, >= 0.4 incoherent) and the sphereflake build ratio
// (<= 1.5).
void writeTargets(std::ostream& out, const std::vector<ThroughputRecord>& records);

// Helpers of the structures' target tables (target_tables.h: grid_report.cpp, kdtree_report.cpp): a scene's measured
// single-thread primary-ray row of a system, a number to three significant digits, and "met" or
// "**not met**".
const ThroughputRecord* primaryRow(const std::vector<ThroughputRecord>& records, const std::string& scene, const std::string& system);
std::string shortNumber(double v);
std::string verdict(bool met);

}  // namespace rtlab::bench
