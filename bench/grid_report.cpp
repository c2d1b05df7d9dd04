#include "bench/grid_report.h"

#include "bench/report.h"
#include "bench/svg_plot.h"
#include "bench/target_tables.h"

#include <algorithm>
#include <cstdio>
#include <iterator>
#include <string>

namespace rtlab::bench {
namespace {

constexpr const char* kBvh = "rtlab:bvh-buckets:12";
const char* const kSweep[] = {"rtlab:grid:C=1", "rtlab:grid:C=3", "rtlab:grid:C=9", "rtlab:grid:C=27", "rtlab:grid:C=81"};
const double kSweepC[] = {1, 3, 9, 27, 81};

// The random soup's line for one grid row: its build and primary trace against the BVH's.
std::string soupLine(const std::vector<ThroughputRecord>& records, const char* system, const char* what) {
    const ThroughputRecord *grid = primaryRow(records, "randsoup", system), *bvh = primaryRow(records, "randsoup", kBvh);
    if (!grid || !bvh || !(grid->buildMs > 0) || !(bvh->mraysPerSecond > 0)) return "";
    double build = bvh->buildMs / grid->buildMs, trace = grid->mraysPerSecond / bvh->mraysPerSecond;
    return "| randsoup | " + std::string(system + 6) + " (" + what + ") builds " + shortNumber(build) +
           "x faster (target >= 10: " + verdict(build >= 10) + "), traces " + shortNumber(trace) +
           "x as fast (target >= 0.8: " + verdict(trace >= 0.8) + ") |\n";
}

// Targets, each where its scene was measured: on randsoup the grid builds at least 10x faster
// and traces primary rays at least 0.8x as fast (one line for the textbook grid:C=27, one for
// fast/'s fastgrid over the same cells); on the bunny at most 8 triangle tests per
// primary ray; on the stadium grid2 traces within 2x of the BVH.
void writeGridTargets(std::ostream& out, const std::vector<ThroughputRecord>& records) {
    std::string lines = soupLine(records, "rtlab:grid:C=27", "the textbook a3 solution") +
                        soupLine(records, "rtlab:fastgrid", "the same cells, tuned in fast/");
    if (const ThroughputRecord* grid = primaryRow(records, "bunny", "rtlab:grid:C=27"); grid && grid->primitiveTestsPerRay) {
        double tests = *grid->primitiveTestsPerRay;
        lines += "| bunny | grid:C=27: " + shortNumber(tests) + " triangle tests per primary ray (target <= 8: " + verdict(tests <= 8) + ") |\n";
    }
    if (const ThroughputRecord *grid = primaryRow(records, "stadium", "rtlab:grid2"), *bvh = primaryRow(records, "stadium", kBvh);
        grid && bvh && bvh->mraysPerSecond > 0) {
        double ratio = grid->mraysPerSecond / bvh->mraysPerSecond;
        const ThroughputRecord* uniform = primaryRow(records, "stadium", "rtlab:grid:C=27");
        lines += "| stadium | grid2 traces " + shortNumber(ratio) + "x as fast as " + std::string(kBvh + 6) + " (target >= 0.5: " +
                 verdict(ratio >= 0.5) + ")" +
                 (uniform && uniform->mraysPerSecond > 0 ? "; the uniform grid:C=27 " + shortNumber(uniform->mraysPerSecond / bvh->mraysPerSecond) + "x" : "") +
                 " |\n";
    }
    if (lines.empty()) return;
    out << "\n### Targets of the grids, single thread, primary rays, against " << (kBvh + 6) << " of this run\n\n"
        << "| scene | figure |\n|---|---|\n"
        << lines;
}

const TargetTableRegistration registration{"grid", writeGridTargets};

}  // namespace

void writeGridSweepSvg(const std::string& path, const std::vector<ThroughputRecord>& records) {
    Plot plot{"Uniform grid: build and trace time against C (cells = C x primitives)", "C", "milliseconds", true, true, {}};
    const char* colours[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b"};
    std::vector<std::string> scenes;
    for (const ThroughputRecord& r : records)
        if (r.system == kSweep[0] && std::find(scenes.begin(), scenes.end(), r.scene) == scenes.end()) scenes.push_back(r.scene);
    for (size_t s = 0; s < scenes.size(); ++s) {
        PlotSeries build{scenes[s] + " build", colours[s % 6], {}, true, true, true};
        PlotSeries trace{scenes[s] + " trace (1,000 primary rays)", colours[s % 6], {}, true, true, false};
        for (size_t k = 0; k < std::size(kSweep); ++k)
            if (const ThroughputRecord* r = primaryRow(records, scenes[s], kSweep[k])) {
                build.points.push_back({kSweepC[k], r->buildMs, ""});
                if (r->mraysPerSecond > 0) trace.points.push_back({kSweepC[k], 1e3 * 1e3 / (r->mraysPerSecond * 1e6), ""});
            }
        plot.series.push_back(build);
        plot.series.push_back(trace);
    }
    if (!plot.series.empty()) writeSvg(path, plot);
}

}  // namespace rtlab::bench
