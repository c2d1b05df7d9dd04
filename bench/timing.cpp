#include "bench/timing.h"

#include <sched.h>
#include <xmmintrin.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <fstream>
#include <thread>

namespace rtlab::bench {

namespace {

using Clock = std::chrono::steady_clock;

// Flush-to-zero and denormals-are-zero for the lifetime of the object, on this thread.
class DenormalsAreZero {
public:
    DenormalsAreZero() : saved_(_mm_getcsr()) { _mm_setcsr(saved_ | 0x8040u); }
    ~DenormalsAreZero() { _mm_setcsr(saved_); }
    DenormalsAreZero(const DenormalsAreZero&) = delete;
    DenormalsAreZero& operator=(const DenormalsAreZero&) = delete;

private:
    unsigned saved_;
};

}  // namespace

PinToCpu0::PinToCpu0() {
    pinned_ = sched_getaffinity(0, sizeof saved_, &saved_) == 0;
    cpu_set_t one;
    CPU_ZERO(&one);
    CPU_SET(0, &one);
    pinned_ = pinned_ && sched_setaffinity(0, sizeof one, &one) == 0;
}

PinToCpu0::~PinToCpu0() {
    if (pinned_) sched_setaffinity(0, sizeof saved_, &saved_);
}

double timedPass(size_t queries, int threads, const ChunkWork& work, TraversalStats& stats) {
    std::atomic<size_t> next{0};
    std::vector<TraversalStats> threadStats(threads);
    auto worker = [&](int index) {
        DenormalsAreZero ftz;
        // Counted on this thread's stack and stored once: neighbouring elements of threadStats
        // share a cache line, and incrementing them from two threads made 2T slower than 1T.
        TraversalStats mine;
        for (;;) {
            size_t begin = next.fetch_add(kRayChunk, std::memory_order_relaxed);
            if (begin >= queries) break;
            work(begin, std::min(kRayChunk, queries - begin), mine);
        }
        threadStats[index] = mine;
    };
    auto start = Clock::now();
    if (threads == 1) {
        worker(0);
    } else {
        std::vector<std::jthread> pool;
        for (int t = 0; t < threads; ++t) pool.emplace_back(worker, t);
    }
    double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    stats = TraversalStats{};
    for (const TraversalStats& s : threadStats) stats += s;
    return seconds;
}

namespace {

// One pass of closest-hit queries over all rays; returns its wall time in seconds.
double tracePass(const BenchSystem& system, const std::vector<BenchRay>& rays, int threads,
                 std::vector<TraceResult>& results, TraversalStats& stats) {
    return timedPass(
        rays.size(), threads,
        [&](size_t begin, size_t count, TraversalStats& mine) {
            system.trace(std::span(rays).subspan(begin, count), results.data() + begin, mine);
        },
        stats);
}

}  // namespace

TraceTiming timeTrace(const BenchSystem& system, const std::vector<BenchRay>& rays, int threads,
                      const TraceProtocol& protocol, std::vector<TraceResult>& results) {
    results.assign(rays.size(), TraceResult{});
    TraceTiming timing;
    tracePass(system, rays, threads, results, timing.stats);  // warm-up
    double total = 0.0, best = 0.0;
    while (timing.passes < protocol.maxPasses && (timing.passes < protocol.minPasses || total < protocol.minSeconds) &&
           !(timing.passes >= 1 && total >= protocol.maxSeconds)) {
        double seconds = tracePass(system, rays, threads, results, timing.stats);
        total += seconds;
        ++timing.passes;
        if (seconds > 0.0) best = std::max(best, static_cast<double>(rays.size()) / seconds * 1e-6);
    }
    timing.bestMraysPerSecond = best;
    return timing;
}

int buildRepeats(size_t triangles) { return triangles < 20'000 ? 50 : triangles < 200'000 ? 10 : 3; }

double medianBuildMs(BenchSystem& system, int threads, int repeats, bool pinToOneCpu) {
    std::optional<PinToCpu0> pin;
    if (pinToOneCpu) pin.emplace();
    system.build(threads);  // warm-up: device and thread-pool creation, page faults
    std::vector<double> ms;
    for (int i = 0; i < repeats; ++i) ms.push_back(system.build(threads));
    std::nth_element(ms.begin(), ms.begin() + ms.size() / 2, ms.end());
    return ms[ms.size() / 2];
}

std::string loadAverage() {
    std::ifstream in("/proc/loadavg");
    std::string a, b, c;
    in >> a >> b >> c;
    return in ? a + " " + b + " " + c : "unknown";
}

}  // namespace rtlab::bench
