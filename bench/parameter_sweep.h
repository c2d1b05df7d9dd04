// Run time against error (b): the bucket count B and the largest leaf maxLeaf of the SAH BVH
// against build time, trace time and SAH cost, with the Pareto front of build against trace
// time (docs/performance.md).
#pragma once

#include "bench/timing.h"

#include <ostream>
#include <string>
#include <vector>

namespace rtlab::bench {

struct ParameterSweepOptions {
    std::string scene = "engine";
    std::string modelsDir;
    std::vector<int> buckets{2, 4, 8, 12, 16, 32};
    std::vector<int> maxLeaf{1, 2, 4, 8, 16};
    bool fullSweep = true;     // also bvh-sah (every split) for each maxLeaf
    size_t rayStride = 4;      // trace every 4th ray of each set
    TraceProtocol protocol{0.3, 3, 20, 5.0};
    int buildRepeats = 3;
};

ParameterSweepOptions quickParameterSweep(ParameterSweepOptions options);

struct ParameterPoint {
    std::string accelerator;  // bvh-buckets:B or bvh-sah
    int buckets = 0;          // 0 for the full sweep
    int maxLeaf = 0;
    double buildMs = 0.0;
    double traceMs = 0.0;     // primary + incoherent sets, scaled to the full 2 x 2^20 rays, 1 thread
    double sahCost = 0.0;
    bool pareto = false;      // no other point is both faster to build and faster to trace
};

std::vector<ParameterPoint> runParameterSweep(const ParameterSweepOptions& options);

void writeParameterMarkdown(std::ostream& out, const ParameterSweepOptions& options,
                            const std::vector<ParameterPoint>& points);
void writeParameterCsv(const std::string& path, const std::vector<ParameterPoint>& points);
void writeParameterSvgs(const std::string& paretoPath, const std::string& sahPath, const ParameterSweepOptions& options,
                        const std::vector<ParameterPoint>& points);

}  // namespace rtlab::bench
