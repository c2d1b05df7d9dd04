// The throughput benchmark (docs/performance.md): every system over every scene, build times,
// Mrays/s for both ray sets on 1 and 2 threads, work per ray, memory, and a ray-by-ray
// comparison with Embree MEDIUM.
#pragma once

#include "bench/timing.h"
#include "framework/scene/benchmark_rays.h"

#include <optional>
#include <string>
#include <vector>

namespace rtlab::bench {

struct ThroughputOptions {
    std::vector<std::string> scenes;
    std::vector<std::string> systems;  // labels to run (rtlab: may be followed by any spec); empty = all
    int maxLeaf = 4;                   // --max-leaf of every rtlab row
    std::string modelsDir;
    size_t rayStride = 1;              // trace every rayStride-th ray (--quick: 16)
    TraceProtocol protocol;
    std::optional<int> buildRepeats;   // default: the reference page's 50 / 10 / 3
    size_t bruteForceLimit = 10'000;   // brute force only up to this many triangles
};

// One row of results.csv: a system on a scene, one ray set, one thread count.
struct ThroughputRecord {
    std::string scene;
    uint32_t triangles = 0;
    std::string system;
    RayKind rays = RayKind::Primary;
    int threads = 1;
    double buildMs = 0.0;
    bool parallelBuild = false;  // the 2T build ran on two threads (else it repeats the 1T figure)
    double mraysPerSecond = 0.0;
    double ratioToEmbreeMedium = 0.0;
    std::optional<double> sahCost;
    std::optional<double> nodeVisitsPerRay;
    std::optional<double> primitiveTestsPerRay;
    std::optional<double> cellStepsPerRay;  // grids: cells the 3D-DDA entered
    std::optional<double> planeStepsPerRay; // KD-trees, BSP trees: split planes the traversal classified
    double bytesPerTriangle = 0.0;
    std::optional<double> referencesPerTriangle;  // rtlab's structures: references kept per triangle
    std::optional<uint64_t> mismatches;  // against Embree MEDIUM; none for Embree MEDIUM itself
    uint64_t hits = 0;
    double sumT = 0.0;
    std::string loadAverage;
    bool measured = true;  // false: skipped or not started, see note
    std::string note;      // why there are no figures, or how they were measured
};

// The labels of every system, in table order: rtlab:brute, rtlab:bvh-median, ...,
// embree:medium, embree:high.
std::vector<std::string> allSystemLabels();

// Runs the benchmark; progress goes to stderr.
std::vector<ThroughputRecord> runThroughput(const ThroughputOptions& options);

// Mismatch between two results (docs/performance.md#embree-setup-and-mismatches): hit/miss
// differs, or |t - tReference| > 1e-4 * max(1, tReference).
bool resultsDiffer(const TraceResult& result, const TraceResult& reference);

}  // namespace rtlab::bench
