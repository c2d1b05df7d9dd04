// How `rtlab compare --blender` and `rtlab refs --blender --parity` print a statistical
// comparison (framework/verification/statistical_comparison.h).
#pragma once

#include "framework/verification/statistical_comparison.h"

#include <iosfwd>
#include <string>

namespace rtlab::cli {

// One line: regions passed, the worst region's relative difference and z, pixel channels
// failed against the allowance, the worst pixel.
std::string statisticalSummary(const StatisticalComparison& c);

// A row per region and channel: ours with its standard error, the reference, the relative
// difference, z.
void printRegionTable(std::ostream& out, const StatisticalComparison& c);

}  // namespace rtlab::cli
