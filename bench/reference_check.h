// --check-reference: the hit counts and sums of t that docs/performance.md#ray-sets
// lists for Embree MEDIUM on the canonical rays, reproduced with Debian's Embree on our scenes
// and rays; and rtlab's reference BVH compared ray by ray with Embree
// (docs/performance.md#embree-setup-and-mismatches: expect 0 to ~20 mismatches per 2^20 rays).
// The ctest bench_reference_hits runs it.
#pragma once

#include <string>
#include <vector>

namespace rtlab::bench {

// Prints a table to stdout; returns true when every figure is within its tolerance.
bool checkReference(const std::vector<std::string>& scenes, const std::string& modelsDir,
                    const std::string& accelerator);

}  // namespace rtlab::bench
