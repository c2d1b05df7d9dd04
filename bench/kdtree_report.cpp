// The KD-tree's part of the bench report (docs/performance.md#kd-trees): its targets against the
// binary bvh-buckets:12 and its own per-node-sort build, all from the same run.
#include "bench/report.h"
#include "bench/target_tables.h"

#include <string>

namespace rtlab::bench {
namespace {

constexpr const char* kKdTree = "rtlab:kdtree";
constexpr const char* kKdTreeSort = "rtlab:kdtree:build=sort";
constexpr const char* kBvh = "rtlab:bvh-buckets:12";

// Targets, each where its scene was measured: at most 6 triangle tests per primary ray on the
// bunny, the engine and the sphereflake; primary throughput at least 1.0x bvh-buckets:12 on the
// engine; on the sphereflake the O(N log N) build at least 4x faster than the per-node sort.
void writeKdTreeTargets(std::ostream& out, const std::vector<ThroughputRecord>& records) {
    std::string lines;
    for (const char* scene : {"bunny", "engine", "sphereflake"})
        if (const ThroughputRecord* kd = primaryRow(records, scene, kKdTree); kd && kd->primitiveTestsPerRay) {
            double tests = *kd->primitiveTestsPerRay;
            lines += std::string("| ") + scene + " | kdtree: " + shortNumber(tests) + " triangle tests per primary ray (target <= 6: " +
                     verdict(tests <= 6) + ") |\n";
        }
    if (const ThroughputRecord *kd = primaryRow(records, "engine", kKdTree), *bvh = primaryRow(records, "engine", kBvh);
        kd && bvh && bvh->mraysPerSecond > 0) {
        double ratio = kd->mraysPerSecond / bvh->mraysPerSecond;
        lines += "| engine | kdtree traces " + shortNumber(ratio) + "x as fast as " + std::string(kBvh + 6) + " (target >= 1.0: " +
                 verdict(ratio >= 1.0) + ") |\n";
    }
    if (const ThroughputRecord *fast = primaryRow(records, "sphereflake", kKdTree), *sorted = primaryRow(records, "sphereflake", kKdTreeSort);
        fast && sorted && fast->buildMs > 0) {
        double ratio = sorted->buildMs / fast->buildMs;
        lines += "| sphereflake | the O(N log N) build is " + shortNumber(ratio) + "x faster than the per-node sort (" +
                 shortNumber(fast->buildMs) + " against " + shortNumber(sorted->buildMs) + " ms; target >= 4: " + verdict(ratio >= 4) + ") |\n";
    }
    if (lines.empty()) return;
    out << "\n### Targets of the KD-tree, single thread, primary rays, against " << (kBvh + 6) << " of this run\n\n"
        << "| scene | figure |\n|---|---|\n"
        << lines;
}

const TargetTableRegistration registration{"kdtree", writeKdTreeTargets};

}  // namespace
}  // namespace rtlab::bench
