// The fast path against Embree MEDIUM, alternating (docs/performance.md#the-race-against-embree):
// the targets of issue 26 measured so that a noisy shared machine cannot decide them.
//
// For each scene, query kind (closest hit on the primary and incoherent rays, any hit on the
// shadow rays) and thread count (1, 2), rtlab's structure and Embree take turns over `rounds`
// rounds, the one that starts alternating from round to round. In a round each side traces the
// whole ray set until `roundSeconds` have passed (at least once) and keeps its best pass; the
// round's ratio is ours over Embree's. A stretch of load then slows both sides of a round, and
// the median of the rounds' ratios, with their spread, is the figure. Builds take turns the same
// way (the 1T build pinned to CPU 0, Embree on one thread; the 2T build unpinned, Embree on two).
#pragma once

#include "bench/bench_system.h"

#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace rtlab::bench {

struct RaceOptions {
    std::vector<std::string> scenes;  // default: bunny, engine, sphereflake
    std::string accelerator;          // default: the fastest structure (fastestAcceleratorType)
    std::string modelsDir;
    std::string embreeIsa;            // default: the best Embree finds on this CPU
    int rounds = 7;                   // at least 5
    double roundSeconds = 0.25;       // per side and round
    size_t rayStride = 1;             // every rayStride-th ray (--quick: 16)
};

// One row: a scene, what was measured, on how many threads, round by round.
struct RaceRow {
    std::string scene;
    std::string kind;  // "primary", "incoherent", "shadow" (Mrays/s) or "build" (ms)
    int threads = 1;
    std::vector<double> ours, embree;  // per round
    std::optional<uint64_t> mismatches;  // queries whose answers differ from Embree's (last pass)
    size_t queries = 0;

    // Per round: ours / Embree's throughput, or Embree's / our build time, so that a ratio of 1
    // or more means at least as fast in every row.
    std::vector<double> ratios() const;
    double medianRatio() const;
};

struct RaceMemory {
    std::string scene;
    double oursBytesPerTriangle = 0.0, embreeBytesPerTriangle = 0.0;
};

struct RaceResult {
    RaceOptions options;
    std::string accelerator;
    std::vector<RaceRow> rows;
    std::vector<RaceMemory> memory;
    std::string loadAtStart, loadAtEnd;
};

// A smoke run: the bunny unless scenes are given, every 16th ray, 5 rounds of one pass each.
RaceOptions quickRace(RaceOptions options);

RaceResult runRace(const RaceOptions& options);

// The rows (median ratio, its spread, the medians of both sides), then one verdict line per
// target of issue 26.
void writeRaceMarkdown(std::ostream& out, const RaceResult& result);

// scene,kind,threads,round,ours,embree,ratio (Mrays/s or ms) and one memory row per scene.
void writeRaceCsv(const std::string& path, const RaceResult& result);

}  // namespace rtlab::bench
