// The timing protocol of docs/performance.md#what-is-measured (Protocol).
//  * Build: one warm-up build, then the median of 50 (< 20k triangles), 10 (< 200k) or 3
//    repeats; "1T" builds run with the process pinned to one CPU.
//  * Trace: the whole ray set per pass, handed out in chunks of 4,096 consecutive rays through
//    an atomic counter to T threads (T = 1 runs on the calling thread), FTZ/DAZ set in every
//    tracing thread; one warm-up pass, then passes until >= minSeconds in total and
//    >= minPasses (at most maxPasses, and no more once maxSeconds have passed); the best pass
//    counts.
#pragma once

#include "bench/bench_system.h"

#include <sched.h>

#include <cstddef>
#include <functional>
#include <vector>

namespace rtlab::bench {

inline constexpr size_t kRayChunk = 4096;

struct TraceProtocol {
    double minSeconds = 1.0;
    int minPasses = 3;
    int maxPasses = 50;
    // Our addition for the slowest rows (median splits on the engine, brute force): once the
    // passes add up to this many seconds, one timed pass is enough.
    double maxSeconds = 10.0;
};

struct TraceTiming {
    double bestMraysPerSecond = 0.0;
    int passes = 0;
    TraversalStats stats;  // of the last pass, all threads
};

// Answers queries [begin, begin + count) and adds its work to stats.
using ChunkWork = std::function<void(size_t begin, size_t count, TraversalStats& stats)>;

// One pass over `queries` queries in chunks of kRayChunk from an atomic counter, on `threads`
// threads (1: the calling thread), FTZ/DAZ on in each; returns its wall time in seconds and the
// work of all threads in stats.
double timedPass(size_t queries, int threads, const ChunkWork& work, TraversalStats& stats);

// Times system.trace over rays; results receives the hits of the last pass.
TraceTiming timeTrace(const BenchSystem& system, const std::vector<BenchRay>& rays, int threads,
                      const TraceProtocol& protocol, std::vector<TraceResult>& results);

// The reference page's repeat count for a build over `triangles`.
int buildRepeats(size_t triangles);

// Warm-up build, then the median of `repeats` builds in ms. With pinToOneCpu the process runs
// on CPU 0 for the duration (as `taskset -c 0` did for the reference's 1T column).
double medianBuildMs(BenchSystem& system, int threads, int repeats, bool pinToOneCpu);

// Pins the process (its calling thread; threads created later inherit it) to CPU 0 for the
// object's lifetime, as `taskset -c 0` did for the reference's 1T builds.
class PinToCpu0 {
public:
    PinToCpu0();
    ~PinToCpu0();
    PinToCpu0(const PinToCpu0&) = delete;
    PinToCpu0& operator=(const PinToCpu0&) = delete;

private:
    cpu_set_t saved_;
    bool pinned_ = false;
};

// The 1-, 5- and 15-minute load averages as "a b c" (the machine is shared; see the docs).
std::string loadAverage();

}  // namespace rtlab::bench
