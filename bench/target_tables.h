// The bench report's target tables, one per structure (docs/performance.md): each structure's
// report file (grid_report.cpp, octree_report.cpp, kdtree_report.cpp) registers its table under
// the accelerator registry's name of the structure, and the report writes them in the
// registry's order of structures. A structure's targets are its report file and nothing else.
#pragma once

#include "bench/throughput.h"

#include <ostream>
#include <string>
#include <vector>

namespace rtlab::bench {

// Writes a structure's targets from the records of one run; nothing when its rows are missing.
using TargetTable = void (*)(std::ostream& out, const std::vector<ThroughputRecord>& records);

// `const TargetTableRegistration registration{"grid", writeGridTargets};` at namespace scope.
struct TargetTableRegistration {
    TargetTableRegistration(std::string structure, TargetTable table);
};

// Every registered table, in the order acceleratorTypes() lists the structures.
void writeStructureTargets(std::ostream& out, const std::vector<ThroughputRecord>& records);

}  // namespace rtlab::bench
